// The zero pattern of a small square matrix M, known from the types of its
// entries, and its block triangular form, found at compile time: a perfect
// matching pairs every unknown with the row that determines it, and the
// strongly connected components of "unknown c needs unknown d" (Tarjan) give
// the blocks in an order that solves each after those it needs.
#pragma once

#include <array>
#include <cstddef>
#include <type_traits>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
namespace kane::detail {

// What is known of a number at compile time: 0, 1, -1 (a column -e_i), or nothing.
enum class entry : unsigned char { zero, one, other, minus_one };

template <std::size_t R, std::size_t C>
using pattern = std::array<std::array<entry, C>, R>;

// No two entries of a equal.
template <class T, std::size_t N>
constexpr bool all_distinct(const std::array<T, N>& a) {
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (a[i] == a[j]) return false;
  return true;
}

template <std::size_t N>
struct block_form {
  std::array<std::size_t, N> row{};        // row[c]: the row that determines unknown c
  std::array<std::size_t, N> order{};      // the unknowns, block after block
  std::array<std::size_t, N + 1> start{};  // block b is order[start[b] .. start[b + 1])
  std::array<std::size_t, N> block{};      // block[c]: the block of unknown c
  std::size_t count = 0;
  bool regular = true;  // a perfect matching exists: M is not structurally singular
};

template <std::size_t N>
struct block_search {
  const pattern<N, N>& m;
  block_form<N> f{};
  std::array<bool, N> seen{};
  std::array<std::size_t, N> index{}, low{}, stack{};
  std::array<bool, N> on_stack{};
  std::size_t counter = 1, top = 0, placed = 0;

  // Kuhn's augmenting path from row r; exact ones are tried first.
  constexpr bool augment(std::size_t r) {
    for (entry kind : {entry::one, entry::other})
      for (std::size_t c = 0; c < N; ++c)
        if (m[r][c] == kind && !seen[c]) {
          seen[c] = true;
          if (f.row[c] == N || augment(f.row[c])) {
            f.row[c] = r;
            return true;
          }
        }
    return false;
  }
  constexpr void connect(std::size_t c) {
    index[c] = low[c] = counter++;
    stack[top++] = c;
    on_stack[c] = true;
    for (std::size_t d = 0; d < N; ++d) {
      if (d == c || m[f.row[c]][d] == entry::zero) continue;
      if (index[d] == 0) {
        connect(d);
        low[c] = low[d] < low[c] ? low[d] : low[c];
      } else if (on_stack[d]) {
        low[c] = index[d] < low[c] ? index[d] : low[c];
      }
    }
    if (low[c] == index[c]) {  // c roots a component; everything it needs is placed already
      f.start[f.count] = placed;
      std::size_t d;
      do {
        d = stack[--top];
        on_stack[d] = false;
        f.block[d] = f.count;
        f.order[placed++] = d;
      } while (d != c);
      ++f.count;
      f.start[f.count] = placed;
    }
  }
  constexpr block_form<N> run() {
    for (std::size_t c = 0; c < N; ++c) f.row[c] = N;
    for (std::size_t r = 0; r < N; ++r) {
      seen = {};
      if (!augment(r)) {
        f.regular = false;
        return f;
      }
    }
    for (std::size_t c = 0; c < N; ++c)
      if (index[c] == 0) connect(c);
    return f;
  }
};

template <std::size_t N>
constexpr block_form<N> blocks_of(const pattern<N, N>& m) {
  return block_search<N>{m}.run();
}

// The pattern of X = M^-1 R: X_cj is exact one when c is a block of its own
// with M_{row c, c} = 1 and R_{row c, j} = 1 and nothing else reaches it.
template <std::size_t N, std::size_t K>
constexpr pattern<N, K> solution_pattern(const pattern<N, N>& m, const block_form<N>& f,
                                         const pattern<N, K>& rhs) {
  pattern<N, K> x{};
  for (std::size_t k = 0; k < N; ++k) {
    const std::size_t b = f.block[f.order[k]];
    for (std::size_t j = 0; j < K; ++j) {
      bool nonzero = false, coupled = false;
      for (std::size_t l = f.start[b]; l < f.start[b + 1]; ++l) {
        const std::size_t c = f.order[l];
        nonzero = nonzero || rhs[f.row[c]][j] != entry::zero;
        for (std::size_t d = 0; d < N; ++d)
          if (f.block[d] != b && m[f.row[c]][d] != entry::zero && x[d][j] != entry::zero) coupled = true;
      }
      const std::size_t c = f.order[k];
      const bool single = f.start[b + 1] - f.start[b] == 1;
      x[c][j] = !(nonzero || coupled) ? entry::zero
                : single && !coupled && m[f.row[c]][c] == entry::one && rhs[f.row[c]][j] == entry::one
                    ? entry::one
                    : entry::other;
    }
  }
  return x;
}

template <std::size_t N>
constexpr pattern<N, N> identity_pattern() {
  pattern<N, N> p{};
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < N; ++j) p[i][j] = i == j ? entry::one : entry::zero;
  return p;
}

// r C + c where p holds a number of its own (entry::other), as one flat array
template <std::size_t R, std::size_t C>
constexpr std::array<bool, R * C> entries_of(const pattern<R, C>& p) {
  std::array<bool, R * C> at{};
  for (std::size_t r = 0; r < R; ++r)
    for (std::size_t c = 0; c < C; ++c) at[r * C + c] = p[r][c] == entry::other;
  return at;
}
// the c where row r of p holds a number of its own
template <std::size_t R, std::size_t C>
constexpr std::array<bool, C> others_in_row(const pattern<R, C>& p, std::size_t r) {
  std::array<bool, C> at{};
  for (std::size_t c = 0; c < C; ++c) at[c] = p[r][c] == entry::other;
  return at;
}
// the c < cols where row r of p is not zero
template <std::size_t R, std::size_t C>
constexpr std::array<bool, C> nonzero_in_row(const pattern<R, C>& p, std::size_t r, std::size_t cols) {
  std::array<bool, C> at{};
  for (std::size_t c = 0; c < cols; ++c) at[c] = p[r][c] != entry::zero;
  return at;
}

}  // namespace kane::detail
#pragma GCC diagnostic pop
