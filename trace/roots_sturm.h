// Sturm-sequence root isolation for polynomials of degree <= N (6 unless asked: a
// sphere_sweep's envelope has degree 10), generic over the scalar type: the tracer
// instantiates it with double, the numerics oracle with 50-digit binary floats.
//
// Sturm's theorem counts the distinct real roots in (a, b] exactly from sign changes, so
// the isolation never loses a root of a stiff (thin-torus) quartic the way a closed form
// can; each isolated root is then finished by safeguarded Newton steps inside its
// bracket.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace povwall::trace {

template <class T, int N = 6>
struct SturmPoly {
    int degree = -1;  // -1: the zero polynomial
    T c[N + 1];       // c[i]: coefficient of x^i

    T operator()(const T& x) const {
        T v = 0;
        for (int i = degree; i >= 0; --i) v = v * x + c[i];
        return v;
    }
};

namespace sturm_detail {

using std::abs;

// -(a mod b), with remainder coefficients below `rel_eps` of the dividend's scale set to
// zero (they are rounding noise; keeping them would invent sign changes).
template <class T, int N>
SturmPoly<T, N> negated_remainder(SturmPoly<T, N> a, const SturmPoly<T, N>& b,
                                  const T& rel_eps) {
    T scale = 0;
    for (int i = 0; i <= a.degree; ++i) scale = std::max(scale, T(abs(a.c[i])));
    for (int k = a.degree - b.degree; k >= 0; --k) {
        T f = a.c[k + b.degree] / b.c[b.degree];
        for (int i = 0; i <= b.degree; ++i) a.c[k + i] -= f * b.c[i];
        a.c[k + b.degree] = 0;
    }
    SturmPoly<T, N> r;
    r.degree = -1;
    for (int i = b.degree - 1; i >= 0; --i) {
        if (abs(a.c[i]) > rel_eps * scale) {
            r.degree = i;
            break;
        }
    }
    for (int i = 0; i <= r.degree; ++i) r.c[i] = -a.c[i];
    return r;
}

}  // namespace sturm_detail

template <class T, int N = 6>
class SturmSequence {
  public:
    explicit SturmSequence(const SturmPoly<T, N>& p) {
        const T rel_eps = T(64) * std::numeric_limits<T>::epsilon();
        seq_[0] = p;
        seq_[1].degree = p.degree - 1;
        for (int i = 1; i <= p.degree; ++i) seq_[1].c[i - 1] = T(i) * p.c[i];
        n_ = 2;
        while (n_ < N + 2 && seq_[n_ - 1].degree > 0) {
            SturmPoly<T, N> r =
                sturm_detail::negated_remainder(seq_[n_ - 2], seq_[n_ - 1], rel_eps);
            if (r.degree < 0) break;  // multiple roots: the last entry is the gcd
            seq_[n_++] = r;
        }
    }
    const SturmPoly<T, N>& poly() const { return seq_[0]; }
    // Sign changes along the sequence at x (zeros skipped).
    int sign_changes(const T& x) const {
        int changes = 0, last = 0;
        for (int i = 0; i < n_; ++i) {
            T v = seq_[i](x);
            int s = v > 0 ? 1 : (v < 0 ? -1 : 0);
            if (s == 0) continue;
            if (last != 0 && s != last) ++changes;
            last = s;
        }
        return changes;
    }

  private:
    SturmPoly<T, N> seq_[N + 2];
    int n_ = 0;
};

template <class T, int N>
T refine_single_root(const SturmSequence<T, N>& seq, T a, T b, int va);

// Distinct real roots of p in (lo, hi], ascending, at most `max_roots`. A cluster
// narrower than the working precision is reported once per root it holds.
template <class T, int N>
int sturm_real_roots(const SturmPoly<T, N>& p, T lo, T hi, T* roots, int max_roots) {
    using std::abs;
    if (p.degree <= 0 || !(lo < hi)) return 0;
    const SturmSequence<T, N> seq(p);
    const T eps = std::numeric_limits<T>::epsilon();
    struct Span {
        T a, b;
        int va, vb;
    };
    Span stack[64];
    int top = 0, found = 0;
    stack[top++] = {lo, hi, seq.sign_changes(lo), seq.sign_changes(hi)};
    // Spans are pushed right half first so roots come out in ascending order.
    while (top > 0 && found < max_roots) {
        Span s = stack[--top];
        int count = s.va - s.vb;
        if (count <= 0) continue;
        T width_floor =
            T(4) * eps * std::max(abs(s.a), abs(s.b)) + std::numeric_limits<T>::min();
        if (count == 1) {
            roots[found++] = refine_single_root(seq, s.a, s.b, s.va);
            continue;
        }
        T m = (s.a + s.b) / 2;
        if (s.b - s.a <= width_floor || top + 2 > 64) {
            for (int k = 0; k < count && found < max_roots; ++k) roots[found++] = m;
            continue;
        }
        int vm = seq.sign_changes(m);
        stack[top++] = {m, s.b, vm, s.vb};
        stack[top++] = {s.a, m, s.va, vm};
    }
    return found;
}

// The one distinct root in (a, b] (va = sign changes at a). Newton steps while they stay
// in the bracket and shrink it; bisection (on the sign of p, or on Sturm counts for a
// root of even multiplicity) otherwise.
template <class T, int N>
T refine_single_root(const SturmSequence<T, N>& seq, T a, T b, int va) {
    using std::abs;
    const SturmPoly<T, N>& p = seq.poly();
    SturmPoly<T, N> dp;
    dp.degree = p.degree - 1;
    for (int i = 1; i <= p.degree; ++i) dp.c[i - 1] = T(i) * p.c[i];
    const T eps = std::numeric_limits<T>::epsilon();
    T fa = p(a), fb = p(b);
    if (fb == 0) return b;
    const bool sign_bracket = (fa < 0) != (fb < 0) && fa != 0;
    T x = (a + b) / 2;
    for (int it = 0; it < 400; ++it) {
        if (b - a <=
            T(2) * eps * std::max(abs(a), abs(b)) + std::numeric_limits<T>::min())
            break;
        T fx = p(x);
        if (fx == 0) return x;
        if (sign_bracket) {
            if ((fx < 0) == (fa < 0)) {
                a = x;
                fa = fx;
            } else {
                b = x;
            }
        } else if (seq.sign_changes(x) == va) {
            a = x;  // the root is right of x
        } else {
            b = x;
        }
        T d = dp(x);
        T nx = d != 0 ? x - fx / d : a;
        x = (nx > a && nx < b) ? nx : (a + b) / 2;
    }
    return x;
}

}  // namespace povwall::trace
