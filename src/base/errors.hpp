#pragma once
/// Errors in two tiers (deal.II Assert/AssertThrow, MFEM MFEM_ASSERT/MFEM_VERIFY):
/// - KILN_ASSERT: programmer errors, checked in debug builds only;
/// - KILN_CHECK_INPUT: user and input errors, always on, throws kiln::InputError.
/// An InputError is raised identically on every rank (inputs and meshes are
/// replicated), so main() prints it once on rank 0 and every rank exits with 1.
/// A failure found on some ranks only goes through check_collectively().

#include <sstream>
#include <stdexcept>
#include <string>

namespace Teuchos
{
template <typename Ordinal> class Comm;
}

namespace kiln
{
/// An error in the user's input (file, parameter, mesh): the message says what,
/// where, what was expected and what to do.
class InputError : public std::runtime_error
{
public:
  explicit InputError(const std::string &message) : std::runtime_error(message) {}
};

/// A run that cannot go on although its input was valid (Newton keeps failing and the
/// time step falls below its minimum). Raised alike on every rank (the decision is
/// taken on reduced quantities); the message says when, what failed and what to try.
/// Output written before it stays valid.
class RunError : public std::runtime_error
{
public:
  explicit RunError(const std::string &message) : std::runtime_error(message) {}
};

/// A failure of one attempted time step that a smaller step may avoid (issue 31): a
/// constitutive model's local Newton solve that did not converge, a value at a quadrature
/// point that is not a finite number. A kernel throws it on the ranks where it happens; the
/// collective evaluation turns it into the same StepFailure on every rank (a RunError on
/// every rank if another rank failed otherwise), the Newton solve ends unconverged and the
/// time stepper repeats the step smaller, as for a Newton solve that does not converge.
/// Where no step can be cut (a steady solve) it ends the run as a RunError.
class StepFailure : public RunError
{
public:
  explicit StepFailure(const std::string &message) : RunError(message) {}
};

/// A file of the run that cannot be written (a full disk, a file-size limit, an I/O error):
/// a RunError (exit 2) after which the run writes nothing more; the files complete before it
/// (the previous checkpoint) stay as they were. Raised alike on every rank.
class WriteError : public RunError
{
public:
  explicit WriteError(const std::string &message) : RunError(message) {}
};

/// A programmer error found by KILN_ASSERT.
class InternalError : public std::logic_error
{
public:
  explicit InternalError(const std::string &message) : std::logic_error(message) {}
};

namespace internal
{
[[noreturn]] void throw_input_error(const std::string &where, const std::string &message);
[[noreturn]] void throw_internal_error(const char *file, int line, const char *condition,
                                       const std::string &message);
} // namespace internal

/// The text of an exception thrown by a Trilinos package (Teuchos' TEUCHOS_TEST_FOR_EXCEPTION
/// and the like) on one line: without the source path and line, "Throw number = N" and
/// "Throw test that evaluated to true: ...", blank lines and trailing spaces; the remaining
/// lines joined by "; ". Other text is returned on one line the same way.
std::string one_line_library_message(const std::string &what);

/// Throws the same InputError on every rank if `local_ok` is false on any rank.
/// `message` is taken from the lowest rank where the check failed.
void check_collectively(const Teuchos::Comm<int> &comm, bool local_ok, const std::string &where,
                        const std::string &message);

/// Throws the same RunError on every rank if `local_ok` is false on any rank (a failure of
/// the run found on some ranks only: an exception in one rank's assembly). `message` is taken
/// from the lowest rank where the check failed. Collective.
void check_run_collectively(const Teuchos::Comm<int> &comm, bool local_ok,
                            const std::string &message);
/// As check_run_collectively(), but what is thrown is a StepFailure if every rank that failed
/// had a step failure (`step_failure` true there), else a RunError. Collective.
void check_run_collectively(const Teuchos::Comm<int> &comm, bool local_ok,
                            const std::string &message, bool step_failure);

/// Throws the same WriteError, "where: message" with the message of the lowest rank that
/// failed, on every rank if `local_ok` is false on any rank. Collective.
void check_write_collectively(const Teuchos::Comm<int> &comm, bool local_ok,
                              const std::string &where, const std::string &message);
} // namespace kiln

#define KILN_CHECK_INPUT(cond, where, msg)                                                         \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::ostringstream kiln_msg_;                                                                \
      kiln_msg_ << msg;                                                                            \
      ::kiln::internal::throw_input_error((where), kiln_msg_.str());                               \
    }                                                                                              \
  } while (false)

#ifdef KILN_DEBUG
#define KILN_ASSERT(cond, msg)                                                                     \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::ostringstream kiln_msg_;                                                                \
      kiln_msg_ << msg;                                                                            \
      ::kiln::internal::throw_internal_error(__FILE__, __LINE__, #cond, kiln_msg_.str());          \
    }                                                                                              \
  } while (false)
#else
#define KILN_ASSERT(cond, msg)                                                                     \
  do                                                                                               \
  {                                                                                                \
  } while (false)
#endif
