// The terms of a poly of order N (POV-Ray 3.7's layout): x^i y^j z^k, i + j + k <= N,
// i from N down to 0, then j from N - i down, then k from N - i - j down.
#pragma once

namespace povwall {

// The highest order: POV-Ray's MAX_ORDER. Its binomial table stops at row 34, so its
// order 35 reads past it (undefined); povwall computes row 35 exactly.
constexpr int kPolyMaxOrder = 35;

// Terms of an order-N poly: (N+1)(N+2)(N+3)/6.
constexpr int poly_term_count(int order) {
    return (order + 1) * (order + 2) * (order + 3) / 6;
}

// The index of x^i y^j z^k among an order-N poly's terms (i + j + k <= N):
// C(a+2, 3) + C(b+1, 2) + c with a = N-i, b = N-i-j, c = N-i-j-k.
constexpr int poly_term_index(int order, int i, int j, int k) {
    const int a = order - i, b = order - i - j, c = order - i - j - k;
    return (a + 2) * (a + 1) * a / 6 + (b + 1) * b / 2 + c;
}

}  // namespace povwall
