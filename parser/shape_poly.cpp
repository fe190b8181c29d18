// The algebraic shapes, as POV-Ray 3.7's Parse_Poly, Parse_Polynom and Parse_Quadric:
//   cubic { <20 floats> }, quartic { <35 floats> }, poly { N, <(N+1)(N+2)(N+3)/6 floats>
//   }, polynomial { N, [xyz(i, j, k): value]... }, quadric { <A,B,C>, <D,E,F>, <G,H,I>, J
//   }
// Every comma is optional.
#include "core/poly_terms.h"
#include "core/quadric.h"
#include "parser/interpreter.h"

namespace povwall::parser {
namespace {

// POV-Ray's MAX_ORDER (35): povwall computes the binomials of order 35 exactly, where
// POV-Ray's table ends at 34 (its order 35 reads past it).
constexpr int kMaxOrder = kPolyMaxOrder;

}  // namespace

double Interpreter::parse_poly_coefficient() {
    const Token at = peek();
    // Parse_Float: a `>` needs parentheses (as in a vector literal).
    const Numeric n = parse_numeric(true);
    if (n.size != 1) error(at, "Float expected but vector or color expression found.");
    return n.c[0];
}

int Interpreter::parse_poly_order(std::string_view message) {
    const Token at = peek();
    // A C cast of the float: poly { 5.9, ... } is order 5.
    const double value = parse_float();
    accept_punct(',');
    if (!(value >= 2 && value < kMaxOrder + 1)) error(at, std::string(message));
    return int(value);
}

void Interpreter::parse_poly(Object& out, int order) {
    Poly poly;
    poly.order = order ? order : parse_poly_order("Order of poly is out of range.");
    const int count = poly_term_count(poly.order);
    expect_punct('<', "to start the poly's coefficients");
    poly.coeffs.resize(size_t(count));
    for (Real& c : poly.coeffs) {
        c = parse_poly_coefficient();
        accept_punct(',');
    }
    expect_punct('>', "after the " + std::to_string(count) + " coefficients of the poly");
    out.shape = std::move(poly);
}

void Interpreter::parse_polynomial(Object& out) {
    Poly poly;
    poly.order = parse_poly_order("Order of polynom is out of range.");
    poly.coeffs.assign(size_t(poly_term_count(poly.order)), 0.0);
    while (accept_word("xyz")) {
        expect_punct('(', "after xyz");
        const Token at = peek();
        double e[3];
        for (int a = 0; a < 3; ++a) {
            e[a] = parse_float();
            if (a < 2) accept_punct(',');
        }
        expect_punct(')', "after the powers of xyz");
        expect_punct(':', "after xyz(i, j, k)");
        const Real value = parse_float();
        accept_punct(',');
        // The powers are unsigned integers (truncated): their sum must not pass the
        // order.
        unsigned int p[3];
        for (int a = 0; a < 3; ++a) {
            if (!(e[a] > -1 && e[a] < kMaxOrder + 1))
                error(at, "Coefficient of polynom is out of range.");
            p[a] = unsigned(e[a]);
        }
        if (p[0] + p[1] + p[2] > unsigned(poly.order))
            error(at, "Coefficient of polynom is out of range.");
        poly.coeffs[size_t(
            poly_term_index(poly.order, int(p[0]), int(p[1]), int(p[2])))] = value;
    }
    out.shape = std::move(poly);
}

void Interpreter::parse_quadric(Object& out) {
    Quadric q;
    q.square = parse_vector();
    accept_punct(',');
    q.mixed = parse_vector();
    accept_punct(',');
    q.linear = parse_vector();
    accept_punct(',');
    q.constant = parse_float();
    // POV-Ray's first box, from the coefficients as written (BOUND_HUGE each way).
    quadric_compute_bbox(q, Vector3(-2e10), Vector3(2e10));
    out.shape = q;
}

void Interpreter::check_algebraic_bounds(const Object& obj, const Token& keyword) {
    if (std::holds_alternative<Poly>(obj.shape) && !obj.clipped_by.empty() &&
        obj.clipped_by->front().inverse) {
        // POV-Ray gives a transformed poly the first clip object's box, inverse or not.
        unsupported(keyword, "a poly whose first clipped_by object is inverse");
    }
}

}  // namespace povwall::parser
