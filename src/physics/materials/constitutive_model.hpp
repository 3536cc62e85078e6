#pragma once
/// The constitutive-model layer (style.md §9, deal.II step-42's ConstitutiveLaw, MOOSE's stress
/// materials): what maps a quadrature point's strain, temperature and state at the previous
/// step to its stress, tangent and new state. Kernels ask a model; they never write a law.
#include <array>
#include <string>
#include <vector>

namespace kiln
{
/// Voigt order used everywhere: xx, yy, zz, xy, xz, yz; strains are TENSOR components
/// (eps_xy, not gamma_xy = 2 eps_xy).
using Voigt = std::array<double, 6>;
/// A 6x6 matrix in Voigt order, [row][column].
using VoigtMatrix = std::array<std::array<double, 6>, 6>;

/// What a model reads at one quadrature point, at the end of the step (time t_{n+1}).
struct PointInput
{
  Voigt strain{};           ///< total strain ε = sym ∇u at t_{n+1} [-]
  double temperature = 0.0; ///< T at t_{n+1} [K]
  /// T at t_n, the last accepted state (the step's start) [K]; T itself where there is none
  /// (Δt = 0: the initial equilibrium, output, the contact pressure of the gap conductance).
  double temperature_old = 0.0;
  double time_step = 0.0; ///< Δt = t_{n+1} − t_n [s] (0: a steady or first solve)
  /// Whether the caller reads the tangent, ∂σ/∂T and the isotropic form (false: a residual
  /// evaluation, which only reads the stress and the new state; a model may then leave them
  /// unset).
  bool derivatives = true;
  /// Whether the caller reads the 6x6 `tangent` where the model also gives the isotropic form
  /// (false: the elasticity kernel, which contracts the form and reads `tangent` only at points
  /// without it; a model that sets `isotropic.valid` may then leave `tangent` unset).
  bool full_tangent = true;
};

/// The isotropic form of a tangent, which a model may give besides the 6x6 matrix:
///   ∂σ/∂ε = λ_t 1⊗1 + 2 μ_t 𝕀 + γ n⊗n,
/// 𝕀 the identity on symmetric tensors and n a symmetric tensor (Voigt order, tensor
/// components), so that tangent[I][J] = λ_t [I, J < 3] + 2 μ_t δ_IJ + γ n_I n_J w_J (w_J = 1
/// for a normal, 2 for a shear component). Isotropic elasticity (γ = 0) and the radial return
/// of the von Mises models have this form; the elasticity kernel then contracts it as it
/// contracts Hooke's law, at a fraction of the cost of the general 6x6 contraction.
struct IsotropicTangent
{
  bool valid = false;    ///< whether the model gave the form (else only `tangent` holds)
  double lambda = 0.0;   ///< λ_t [Pa]
  double shear = 0.0;    ///< μ_t [Pa]
  double rank_one = 0.0; ///< γ [Pa]
  Voigt n{};             ///< n [-] (not read when γ = 0)

  /// The 6x6 tangent of the form (Voigt, tensor shears: tangent[I][J] as PointResponse's).
  VoigtMatrix matrix() const;
};

/// What a model returns at one quadrature point.
struct PointResponse
{
  Voigt stress{}; ///< σ at t_{n+1} [Pa]
  /// ∂σ_I/∂ε_J [Pa], the consistent (algorithmic) tangent, with ε_J a tensor component: a
  /// shear column J >= 3 is the derivative with respect to ε_xy = ε_yx moved together (so
  /// isotropic elasticity has tangent[3][3] = 2G).
  VoigtMatrix tangent{};
  Voigt stress_temperature_derivative{}; ///< ∂σ/∂T at fixed ε [Pa/K]
  /// The same tangent in isotropic form, if the model gives it (`valid`; equal to `tangent`
  /// up to rounding).
  IsotropicTangent isotropic{};
};

/// A constitutive model with state. State is n_state() doubles per quadrature point, owned by
/// the caller (a QuadratureState): evaluate() reads the state at t_n (`old_state`, as last
/// committed) and writes the state at t_{n+1} (`new_state`); it must not keep pointers. On
/// entry `new_state` holds what the point's last evaluation wrote (the committed state after
/// a commit or a restore, zeros or the initial state outside a run): a model may read it as the
/// start of a local iteration, never as data: the same (input, old_state) gives the same
/// response to the model's local tolerance whatever `new_state` holds (Newton re-evaluates a
/// point many times in a step; a rejected step restores `old_state`). Thread-safe: const and
/// no caches.
class ConstitutiveModel
{
public:
  virtual ~ConstitutiveModel() = default;

  /// Doubles of state per quadrature point (0 for an elastic model).
  virtual int n_state() const { return 0; }
  /// The state before the first step (`state` has n_state() entries). Default: zeros.
  virtual void initial_state(double *state) const;
  /// Names of the state components, for checkpoints (n_state() entries, stable across
  /// versions: a checkpoint is read back by name).
  virtual std::vector<std::string> state_names() const { return {}; }

  /// Stress, tangent and ∂σ/∂T at `in`, from `old_state`; writes `new_state` (both n_state()
  /// entries; either may be null when n_state() == 0). Throws StepFailure (base/errors.hpp) if the
  /// point cannot be integrated (a local Newton solve that does not converge, a strain that is not
  /// a number): the time stepper then cuts the step.
  virtual void evaluate(const PointInput &in, const double *old_state, double *new_state,
                        PointResponse &out) const = 0;

  /// Whether σ is linear in (ε, T) with a constant tangent and no state (isotropic linear
  /// thermo-elasticity with constant properties): the Jacobian is then constant and reused,
  /// and kernels may take their fast path through lame_constants().
  virtual bool constant_linear() const { return false; }

  /// The thermal strain ε_th(T) each normal component carries at temperature T (isotropic:
  /// ε_th I; with a coefficient of T the secant one, doc/materials.md) [-], for the output.
  virtual double thermal_strain(double temperature) const = 0;

  /// Output fields per point beyond the stress: equivalent plastic strain [-], its rate
  /// [1/s] (both 0 for an elastic model).
  virtual double equivalent_plastic_strain(const double * /*state*/) const { return 0.0; }
  virtual double plastic_strain_rate(const double * /*state*/) const { return 0.0; }
};
} // namespace kiln
