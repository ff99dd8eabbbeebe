// The kinematic differential equations at a state: with
// u = Y q' + Z, q' = W u + X with W = Y^-1 and X = -W Z (both depend on q
// alone), and q'' = W (u' - Y' q' - Z'). Y's zero pattern is known at compile
// time (speeds/kinematic_weights.hpp): W is found block by block
// (evaluation/block_solve.hpp) and only its numbers are stored.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include "kane/detail/choices.hpp"
#include "kane/detail/structure.hpp"
#include "kane/evaluation/block_solve.hpp"
#include "kane/evaluation/evaluate.hpp"
#include "kane/evaluation/orthogonal_solve.hpp"
#include "kane/evaluation/status.hpp"
#include "kane/frames/state.hpp"
#include "kane/speeds/kinematic_weights.hpp"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// The speed set, or none where the argument is not one (its error is reported, and no other follows).
template <class Speeds>
using usable_speeds = std::conditional_t<std::is_void_v<Speeds> || SpeedSet<Speeds>, Speeds, void>;

// Speeds: void to read q' and q'' from the state; a speed set to solve them from u and u'.
template <class St, class Speeds>
class kinematic_equations {
 protected:
  static constexpr bool solves = !std::is_void_v<Speeds>;
  // q' = u or q' read from the state (or no speed set: refused by the constructor)
  static constexpr bool direct = [] {
    if constexpr (SpeedSet<Speeds>)
      return Speeds::identity;
    else
      return true;
  }();
  static constexpr std::size_t nq = St::nq;
  static constexpr std::size_t nd = [] {  // the speeds q' define; rows nd..nq-1 are held (u = 0 there)
    if constexpr (solves)
      return Speeds::defined;
    else
      return nq;
  }();

 public:
  using scalar = typename St::scalar;
  using matrixn = Eigen::Matrix<scalar, int(nq), int(nq)>;
  using vectorn = Eigen::Matrix<scalar, int(nq), 1>;

  status_of<scalar> status() const { return status_; }
  // q' = W u + X (W the identity and X zero without a speed set).
  matrixn W() const {
    matrixn w;
    for (std::size_t i = 0; i < nq; ++i)
      for (std::size_t j = 0; j < nq; ++j) w(i, j) = weight(i, j);
    return w;
  }
  vectorn X() const {
    vectorn x;
    for (std::size_t i = 0; i < nq; ++i) x(i) = offset(i);
    return x;
  }

  // W_sr and X_s (0-based): numbers where the structure of Y does not fix them.
  scalar weight(std::size_t s, std::size_t r) const {
    const auto kind = w_pattern()[s][r];
    if constexpr (!direct)
      if (kind == entry::other) return kde_w_[s][r];
    return scalar(kind == entry::one);
  }
  scalar offset(std::size_t s) const {
    if constexpr (!direct)
      if (offset_pattern()[s]) return kde_x_[s];
    return scalar(0);
  }
  // the stored numbers behind kde_weight<S + 1, R + 1> and kde_offset<S + 1>
  template <std::size_t S, std::size_t R>
  scalar stored_weight() const {
    static_assert(w_pattern()[S][R] == entry::other);
    return kde_w_[S][R];
  }
  template <std::size_t S>
  scalar stored_offset() const {
    static_assert(offset_pattern()[S]);
    return kde_x_[S];
  }

 protected:
  KANE_ALWAYS_INLINE kinematic_equations() {  // NaN until the first update
    fill_nan(qd_), fill_nan(qdd_);
    if constexpr (!direct)
      if constexpr (Speeds::rows == nq)  // W's numbers and X (weight and offset read no other entry)
        static_for_where<stored_entries()>([&](auto rc) {
          constexpr std::size_t r = rc / nq, c = rc % nq;
          if constexpr (system::x[r][c] == entry::other)
            kde_w_[r][c] = std::numeric_limits<scalar>::quiet_NaN();
          if constexpr (c == 0 && system::offset[r]) kde_x_[r] = std::numeric_limits<scalar>::quiet_NaN();
        });
    static_assert(!solves || SpeedSet<Speeds>,
                  "kane: the fourth argument of evaluator is a speed set (speeds/generalized_speeds.hpp)");
    if constexpr (solves) {
      static_assert(Speeds::rows == nq,
                    "kane: a speed set defines as many speeds as the state has coordinates (held rows, "
                    "such as kane::unit_norm, included)");
      static_assert(St::nu >= Speeds::n, "kane: the state holds fewer speeds than the speed set defines");
      if constexpr (!Speeds::identity)
        static_assert(system::form.regular,
                      "kane: these speeds do not determine q' (Y = du/dq' is singular at every state: some "
                      "q' appears in no speed, or fewer speeds than q' involve them)");
    }
  }

  // q_I' (D = 1) or q_I'' (D = 2) as solved.
  template <std::size_t I, std::size_t D>
  scalar rate() const {
    return D == 1 ? qd_[I - 1] : qdd_[I - 1];
  }

  template <std::size_t R>
  static constexpr auto definition() {
    return std::get<R>(Speeds::definitions);
  }
  using system = kde_system<std::conditional_t<solves, Speeds, qdot_speeds<1>>>;
  // the entries of W and X stored as numbers (X_r at r nq)
  static constexpr std::array<bool, nq * nq> stored_entries() {
    auto at = entries_of(system::x);
    for (std::size_t r = 0; r < nq; ++r) at[r * nq] = at[r * nq] || system::offset[r];
    return at;
  }
  static constexpr pattern<nq, nq> w_pattern() {
    if constexpr (direct)
      return identity_pattern<nq>();
    else
      return system::x;
  }
  static constexpr std::array<bool, nq> offset_pattern() {
    if constexpr (direct)
      return {};
    else
      return system::offset;
  }

  // Y q' + Z = u, so q' = W u + X with W = Y^-1 (evaluation/block_solve.hpp) and X = -W Z:
  // W and X depend on q alone. The zeros and ones of W are written once, by the constructor.
  // status_ holds the check of the state; a failure there or here makes W's numbers and X NaN.
  template <class Ev>
  KANE_ALWAYS_INLINE void solve_kinematic_equations(const Ev& ev) {
    table<scalar, nq, nq> y;
    static_for_where<entries_of(system::m)>([&](auto rc) {
      constexpr std::size_t r = rc / nq, c = rc % nq;
      constexpr auto e = diff(definition<r>(), coordinate<c + 1, 1>{});  // built by the constant evaluator
      y[r][c] = eval_scalar(e, ev);
    });
    const status_of<scalar> solved = [&] {
      if constexpr (!direct && orthogonal_form<system>())
        return solve_orthogonal<system, inverse_norms<system, Speeds, typename Ev::closure>()>(y, kde_w_);
      else
        return solve_structured<system, known_entries::left>(y, y, kde_w_);
    }();
    then(status_, solved);
    std::array<scalar, nq> z;
    static_for<nq>([&](auto r) {
      if constexpr (system::z[r] != entry::zero) {
        constexpr auto e = at_rest(definition<r>());
        z[r] = -eval_scalar(e, ev);
      }
    });
    auto finite = truth<scalar>(true);  // X = -W Z may overflow where W does not
    static_for<nq>([&](auto c) {
      if constexpr (system::offset[c]) {
        kde_x_[c] = apply_row<c, map::linear, nq>(z);
        finite = finite & (kde_x_[c] - kde_x_[c] == scalar(0));
      }
    });
    fail_unless(status_, finite, solve_status::not_finite);
    const auto spoil = nan_unless_rare<scalar>(ok_of<scalar>(status_));
    static_for_where<stored_entries()>([&](auto rc) {
      constexpr std::size_t r = rc / nq, c = rc % nq;
      if constexpr (system::x[r][c] == entry::other) spoil(kde_w_[r][c]);
      if constexpr (c == 0 && system::offset[r]) spoil(kde_x_[r]);
    });
  }
  // q' (NaN if status_ is not ok; not_finite if q' = W u + X overflows). checking::at_end: q' unchecked.
  template <checking C = checking::each>
  KANE_ALWAYS_INLINE void solve_rates(const St& s) {
    if constexpr (direct) {  // u = q'
      for (std::size_t i = 0; i < nq; ++i) qd_[i] = s.u[i];
    } else {
      qd_ = apply<map::affine, nd>(s.u);
    }
    if constexpr (C == checking::each) {
      fail_unless(status_, all_finite(qd_), solve_status::not_finite);
      nan_where_failed<scalar>(status_, qd_);  // a branch for one state, as for q'': products measured slower
    }
  }
  // (W v)_c (+ X_c) for v zero beyond its first Cols entries, skipping the zeros of W and X.
  template <std::size_t C, map Kind, std::size_t Cols, class V>
  KANE_ALWAYS_INLINE scalar apply_row(const V& v) const {
    scalar sum = scalar(0);
    if constexpr (Kind == map::affine && system::offset[C]) sum = kde_x_[C];
    static_for_where<nonzero_in_row(system::x, C, Cols)>([&](auto j) {
      if constexpr (system::x[C][j] == entry::one)
        sum += v[j];
      else
        sum += kde_w_[C][j] * v[j];
    });
    return sum;
  }
  template <map Kind, std::size_t Cols, class V>
  KANE_ALWAYS_INLINE std::array<scalar, nq> apply(const V& v) const {
    std::array<scalar, nq> out;
    static_for<nq>([&](auto c) { out[c] = apply_row<c, Kind, Cols>(v); });
    return out;
  }

  struct every_coordinate {
    static constexpr std::array<bool, nq> qdd = every<nq>();
  };
  // u' = Y q'' + Y' q' + Z', so q'' = W (u' - Y' q' - Z'): the q_c'' of Reads::qdd only (the
  // rows of u' - Y' q' - Z' that W mixes into them), the others NaN.
  template <class Reads = every_coordinate, class Ev>
  KANE_ALWAYS_INLINE void solve_accelerations(const Ev& ev, const St& s) {
    const scalar nan = std::numeric_limits<scalar>::quiet_NaN();
    if constexpr (Speeds::identity) {
      static_for<nq>([&](auto i) { qdd_[i] = Reads::qdd[i] ? s.ud[i] : nan; });
    } else {
      constexpr auto rows = [] {
        std::array<bool, nq> r{};
        for (std::size_t c = 0; c < nq; ++c)
          for (std::size_t j = 0; j < nq; ++j)
            r[j] = r[j] || (Reads::qdd[c] && system::x[c][j] != entry::zero);
        return r;
      }();
      std::array<scalar, nq> v;
      static_for<nq>([&](auto r) {
        if constexpr (rows[r]) {
          scalar sum = scalar(0);  // u' = 0 in held rows
          if constexpr (r < nd) sum = s.ud[r];
          constexpr auto zd = dt(at_rest(definition<r>()));
          if constexpr (!is_zero_v<std::remove_cv_t<decltype(zd)>>) sum -= eval_scalar(zd, ev);
          static_for_where<others_in_row(system::m, r)>([&](auto c) {  // Y' = 0 at constants
            constexpr auto yd = dt(diff(definition<r>(), coordinate<c + 1, 1>{}));
            if constexpr (!is_zero_v<std::remove_cv_t<decltype(yd)>>) sum -= eval_scalar(yd, ev) * qd_[c];
          });
          v[r] = sum;
        }
      });
      static_for<nq>([&](auto c) {
        if constexpr (Reads::qdd[c])
          qdd_[c] = apply_row<c, map::linear, nq>(v);
        else
          qdd_[c] = nan;
      });
    }
    if constexpr (checking_of<Reads> == checking::each) {
      auto finite = truth<scalar>(true);
      static_for<nq>([&](auto c) {
        if constexpr (Reads::qdd[c]) finite = finite & (qdd_[c] - qdd_[c] == scalar(0));
      });
      fail_unless(status_, finite, solve_status::not_finite);
      nan_where_failed<scalar>(status_, qdd_);
    }
  }

  status_of<scalar> status_{};
  // held only where solved (nr) and where Y is no identity (nw)
  static constexpr std::size_t nr = solves ? nq : 0, nw = direct ? 0 : nq;
  std::array<scalar, nr> qd_, qdd_;  // read at the velocity level and above
  table<scalar, nw, nw> kde_w_;      // W where its structure does not fix it
  std::array<scalar, nw> kde_x_;
};

}  // namespace kane::detail
#pragma GCC diagnostic pop
