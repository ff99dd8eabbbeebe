// What a numeric solve found: ok, a singular matrix (a pivot at or below the
// rank threshold), or numbers that are not finite (NaN or inf in or out).
#pragma once

namespace kane {

enum class solve_status { ok, singular, not_finite };

}  // namespace kane
