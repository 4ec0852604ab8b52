#include "implicitizer/sdf/scene_frame.hpp"

#include <vector>

#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

Rational abs_of(const Rational& q) { return q < Rational(0) ? -q : q; }

// The float nearest to q (through double; q is within float's normal range here).
Rational round_to_float(const Rational& q) {
  return Rational(static_cast<double>(static_cast<float>(to_mpq(q).get_d())));
}

InputError invalid_box(const std::string& message) { return InputError("invalid_box", message).in_field("box"); }

}  // namespace

SceneBox SceneBox::default_box() {
  return SceneBox{{Rational(-2), Rational(-2), Rational(-2)}, {Rational(2), Rational(2), Rational(2)}};
}

SceneFrame make_scene_frame(const SceneBox& box) {
  // 1e-30 and 1e30 as exact rationals.
  const Rational big = to_rational(Integer("1" + std::string(30, '0')));
  const Rational small = Rational(1) / big;
  SceneFrame frame{{}, Rational(0)};
  Rational half_extent(0);
  for (std::size_t i = 0; i < 3; ++i) {
    if (!(box.hi[i] > box.lo[i])) {
      throw invalid_box("the box must have hi > lo on every axis (axis " + std::to_string(i) + ")");
    }
    frame.centre[i] = (box.lo[i] + box.hi[i]) / Rational(2);
    const Rational half = (box.hi[i] - box.lo[i]) / Rational(2);
    if (half > half_extent) half_extent = half;
    const Rational c = abs_of(frame.centre[i]);
    if (c > big) throw invalid_box("the box's centre must be at most 1e30 in magnitude on every axis");
    // Any point near the middle serves as the frame's origin: a centre below
    // float's range becomes 0 (an offset of at most 1e-30, far below any box side).
    if (c < small) frame.centre[i] = Rational(0);
  }
  if (half_extent > big || half_extent < small) {
    throw invalid_box("the box's largest half side must be between 1e-30 and 1e30");
  }
  for (Rational& c : frame.centre) c = round_to_float(c);
  frame.scale = round_to_float(Rational(1) / half_extent);
  return frame;
}

Polynomial frame_polynomial(const Polynomial& f, const SceneFrame& frame, const Budget& budget) {
  if (f.is_constant()) throw InputError("constant_polynomial", "a constant polynomial has no surface");
  const RingPtr& ring = f.ring();
  std::vector<Polynomial> values;
  for (std::size_t i = 0; i < 3; ++i) {
    values.push_back(Polynomial::constant(ring, frame.centre[i]) +
                     Polynomial::variable(ring, i).divided_by(frame.scale));
  }
  const Polynomial g = f.compose(ring, values, budget);
  Rational largest(0);
  for (std::size_t i = 0; i < g.num_terms(); ++i) {
    const Rational a = abs_of(g.coefficient(i));
    if (a > largest) largest = a;
  }
  return g.divided_by(largest);
}

}  // namespace implicitizer
