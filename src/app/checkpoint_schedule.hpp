#pragma once
/// The "Checkpoint" block: when a run writes its checkpoints, and where.
#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

namespace kiln
{
/// Checkpoints (io/checkpoint.hpp) at listed times (the steps land on them), every N
/// accepted steps, and at the end of a run; and always when a run is stopped by SIGTERM or
/// SIGINT or by an error, so that it can go on from its last good state. Each is written as
/// BASE-NNNNNN.h5 (NNNNNN: the accepted steps), and BASE.h5 is the latest one.
class CheckpointSchedule
{
public:
  static Teuchos::ParameterList valid_parameters();
  /// `p` validated against valid_parameters(); `output_base` is the results' path without
  /// extension (the default base is OUTPUT_BASE.checkpoint); `where` names the block.
  CheckpointSchedule(const Teuchos::ParameterList &p, const std::string &output_base,
                     const std::string &where);

  const std::vector<double> &times() const { return times_; }
  /// Whether a checkpoint is due after the accepted step `steps` (every N steps).
  bool due_after_step(const int steps) const { return every_ > 0 && steps % every_ == 0; }
  bool at_end() const { return at_end_; }
  /// BASE-NNNNNN.h5 for the state after `steps` accepted steps.
  std::string path(int steps) const;
  /// BASE.h5, the latest checkpoint.
  std::string latest_path() const { return base_ + ".h5"; }
  /// The path of the checkpoints without extension.
  const std::string &base() const { return base_; }

private:
  std::vector<double> times_;
  int every_;
  bool at_end_;
  std::string base_;
};
} // namespace kiln
