#include "app/checkpoint_schedule.hpp"

#include "base/errors.hpp"
#include "base/parameters.hpp"

#include <Teuchos_Array.hpp>

#include <cstdio>

namespace kiln
{
Teuchos::ParameterList CheckpointSchedule::valid_parameters()
{
  Teuchos::ParameterList p("Checkpoint");
  p.set("Times", Teuchos::Array<double>(),
        "times at which a checkpoint is written, increasing, >= 0, at most the end of the run "
        "(the last output time); the steps land on them [s]");
  p.set("Every Steps", 0, "a checkpoint every this many accepted steps; 0: none [count]",
        nonnegative_int_validator());
  p.set("At End", true,
        "a checkpoint when the run reaches its last output time [-]. A run stopped by SIGTERM, "
        "SIGINT or SIGUSR1, or by an error, always writes one of its last good state");
  p.set("File Base", "",
        "path of the checkpoints without extension: BASE-NNNNNN.h5 after NNNNNN accepted "
        "steps, and BASE.h5 the latest; the default \"\" means <Output File Base>.checkpoint. "
        "Continue a run with kiln INPUT.xml --restart BASE.h5");
  return p;
}

CheckpointSchedule::CheckpointSchedule(const Teuchos::ParameterList &p,
                                       const std::string &output_base, const std::string &where)
    : every_(p.get<int>("Every Steps")), at_end_(p.get<bool>("At End")),
      base_(p.get<std::string>("File Base"))
{
  const auto &times = p.get<Teuchos::Array<double>>("Times");
  for (int i = 0; i < times.size(); ++i)
    KILN_CHECK_INPUT(times[i] >= 0.0 && (i == 0 || times[i] > times[i - 1]), where + "/\"Times\"",
                     "checkpoint times must be >= 0 and increasing; entry " << i + 1 << " is "
                                                                            << times[i]);
  times_.assign(times.begin(), times.end());
  if (base_.empty())
    base_ = output_base + ".checkpoint";
}

std::string CheckpointSchedule::path(const int steps) const
{
  char number[16];
  std::snprintf(number, sizeof number, "%06d", steps);
  return base_ + "-" + number + ".h5";
}
} // namespace kiln
