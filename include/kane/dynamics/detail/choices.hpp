// The choices the passes of the dynamics take, named where a call makes them.
#pragma once

namespace kane::detail {

// The u' the equations take: the state's, or 0 (motion's state, whose u' they solve for).
enum class rates : bool { of_state, at_rest };
// tau = M u' - f, or -tau (at rest, -tau is the forcing f).
enum class sign : bool { plus, minus };
// What Kane's sums compute: M and f, M alone, or f alone where M is known at compile time.
enum class parts { both, mass_matrix, forcing };

}  // namespace kane::detail
