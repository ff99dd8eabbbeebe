// Spatial vectors for the passes in the root's components (rnea_derivatives.hpp): motions
// (angular; linear of the point at O) and forces (moment about O; force), their cross products,
// a composite inertia about O and its variation B with the velocity.
#pragma once

#include <cstddef>
#include <type_traits>

#include "kane/detail/inline.hpp"
#include "kane/detail/v3.hpp"
#include "kane/dynamics/detail/tree/composite_inertia.hpp"
#include "kane/dynamics/detail/tree/turns.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

template <class S>
struct spatial {
  v3<S> w, v;
};
template <class S>
KANE_ALWAYS_INLINE spatial<S> operator+(const spatial<S>& a, const spatial<S>& b) {
  return {a.w + b.w, a.v + b.v};
}
template <class S>
KANE_ALWAYS_INLINE spatial<S> operator*(const S& s, const spatial<S>& a) {
  return {s * a.w, s * a.v};
}
template <class S>
KANE_ALWAYS_INLINE S dot6(const spatial<S>& a, const spatial<S>& b) {
  return dot3(a.w, b.w) + dot3(a.v, b.v);
}
template <class S>  // motion x motion
KANE_ALWAYS_INLINE spatial<S> cross_motion(const spatial<S>& a, const spatial<S>& b) {
  return {cross3(a.w, b.w), cross3(a.w, b.v) + cross3(a.v, b.w)};
}
template <class S>  // motion x* force
KANE_ALWAYS_INLINE spatial<S> cross_force(const spatial<S>& a, const spatial<S>& f) {
  return {cross3(a.w, f.w) + cross3(a.v, f.v), cross3(a.w, f.v)};
}
template <class S>  // Y x
KANE_ALWAYS_INLINE spatial<S> times(const composite_inertia<S>& y, const spatial<S>& x) {
  return {sym_times(y.i, x.w) + cross3(y.h, x.v), y.mass * x.v - cross3(y.h, x.w)};
}
template <class S>
struct variation {  // B = [Z - [l_w], 0; -2 [l_v], 0]
  sym3<S> z;
  v3<S> lw, lv;
  KANE_ALWAYS_INLINE spatial<S> times(const spatial<S>& x) const {
    return {sym_times(z, x.w) + cross3(x.w, lw), S(2) * cross3(x.w, lv)};
  }
  KANE_ALWAYS_INLINE v3<S> transposed_times(const spatial<S>& y) const {  // B^T y: its angular part
    return sym_times(z, y.w) + cross3(lw, y.w) + S(2) * cross3(lv, y.v);
  }
};
template <class S>
KANE_ALWAYS_INLINE void add_to(composite_inertia<S>& a, const composite_inertia<S>& b) {
  a.mass = a.mass + b.mass, a.h = a.h + b.h, a.i = a.i + b.i;
}
template <class S>
KANE_ALWAYS_INLINE void add_to(variation<S>& a, const variation<S>& b) {
  a.z = a.z + b.z, a.lw = a.lw + b.lw, a.lv = a.lv + b.lv;
}
// R x with R by its columns
template <class S>
KANE_ALWAYS_INLINE v3<S> by_columns(const m3<S>& r, const v3<S>& x) {
  return x.x * r[0] + x.y * r[1] + x.z * r[2];
}
// A composite about o (in the components of R's frame, o at p) about O in the root's.
template <class S>
KANE_ALWAYS_INLINE composite_inertia<S> about_root(const composite_inertia<S>& q, const m3<S>& r,
                                                   const v3<S>& p) {
  const v3<S> h = by_columns(r, q.h);
  const m3<S> ri{by_columns(r, {q.i[0], q.i[3], q.i[5]}), by_columns(r, {q.i[3], q.i[1], q.i[4]}),
                 by_columns(r, {q.i[5], q.i[4], q.i[2]})};  // R I by columns
  const auto rir = [&](auto a, auto b) {                    // (R I R^T)_ab
    return comp<a>(ri[0]) * comp<b>(r[0]) + comp<a>(ri[1]) * comp<b>(r[1]) + comp<a>(ri[2]) * comp<b>(r[2]);
  };
  using I0 = std::integral_constant<std::size_t, 0>;
  using I1 = std::integral_constant<std::size_t, 1>;
  using I2 = std::integral_constant<std::size_t, 2>;
  const S d = q.mass * dot3(p, p) + S(2) * dot3(p, h);
  const v3<S> g = q.mass * p + h;  // -(m p p^T + p h^T + h p^T) = -(p g^T + h p^T)
  return {q.mass, g,
          sym3<S>{rir(I0{}, I0{}) + d - p.x * g.x - h.x * p.x, rir(I1{}, I1{}) + d - p.y * g.y - h.y * p.y,
                  rir(I2{}, I2{}) + d - p.z * g.z - h.z * p.z, rir(I0{}, I1{}) - p.x * g.y - h.x * p.y,
                  rir(I1{}, I2{}) - p.y * g.z - h.y * p.z, rir(I2{}, I0{}) - p.z * g.x - h.z * p.x}};
}
// B of Y at the velocity v, l = Y v.
template <class S>
KANE_ALWAYS_INLINE variation<S> variation_of(const composite_inertia<S>& y, const spatial<S>& v,
                                             const spatial<S>& l) {
  const v3<S> w = v.w;
  const v3<S> c0 = cross3(w, v3<S>{y.i[0], y.i[3], y.i[5]}), c1 = cross3(w, v3<S>{y.i[3], y.i[1], y.i[4]}),
              c2 = cross3(w, v3<S>{y.i[5], y.i[4], y.i[2]});  // [w] I by columns
  const S d = S(2) * dot3(y.h, v.v);
  const v3<S> h = y.h, u = v.v;
  return {sym3<S>{S(2) * (c0.x - h.x * u.x) + d, S(2) * (c1.y - h.y * u.y) + d, S(2) * (c2.z - h.z * u.z) + d,
                  c1.x + c0.y - h.x * u.y - u.x * h.y, c2.y + c1.z - h.y * u.z - u.y * h.z,
                  c0.z + c2.x - h.z * u.x - u.z * h.x},
          l.w, l.v};
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
