// The enumerators of the closed options (core/option.hpp) that a Scene member holds, typed: the
// scene reader parses the value once (Param's store through the Option), and every output writes
// the option's name of it back. Each Option, the one list of names, is declared next to the code
// that reads it; its enumerators are here, below the Scene. (method.projection's are in
// core/projection_method.hpp, with its Option.)
#pragma once

namespace arksph {

// method.ppe_operator (projection/projection_options.hpp): the Laplacian of the PPE, C&R eq. 19 or eq. 18.
enum class PpeOperator { approximate, exact };
// method.projection_points (projection/projection_options.hpp): after each accepted step, or also
// after every ERK stage.
enum class ProjectionPoints { step, stages };
// method.neighbor_storage (rhs/neighbor_cache.hpp): the kernel values stored per pair, or only the candidates.
enum class NeighborStorage { pairs, candidates };
// time.steady_measure (diagnostics/steady_state.hpp): the rate over window means or over intervals.
enum class SteadyMeasure { window_means, intervals };

// The closed options with an "auto" rule: the Scene member is a std::optional of the enumerator,
// empty while the key reads "auto" and set once the rule has chosen (io/scene_defaults.hpp).
// method.ppe_divergence (projection/projection_options.hpp): the PPE's source, C&R eq. 17 or
// Szewc et al. 2012 eq. 19.
enum class PpeDivergence { cummins_rudman, difference };
// method.ppe_pressure_level (projection/projection_options.hpp): the free level of P of the
// Neumann problem.
enum class PressureLevel { zero_mean, zero_min };
// method.body_force_pressure (rhs/pressure_gravity.hpp): the pressure equation solves for
// P = p - rho0 g . r, or g stays in the momentum equation.
enum class BodyForcePressure { modified, split };

}  // namespace arksph
