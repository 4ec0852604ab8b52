#pragma once
/// \file
/// The side of an approximated sheet: a signed companion of its unsigned value.
///
/// A sheet's value is >= 0 on both sides of the surface, so neither a renderer's hit
/// rule nor its shading can tell which side a ray comes from, nor see a step that
/// jumps across the surface (mode fast: F/|∇F| is not a bound). For an exact sheet the
/// renderers read the sign of F (render_target.hpp; the page's side function). An
/// approximation is a union of pieces q_k = 0, each in its own frame: its side is the
/// signed fast estimate q_k/|∇q_k| (a solid's value, FastSdf) of the piece whose |estimate|
/// is smallest at p. On piece k's sheet that piece's estimate is 0, so the side's sign
/// changes as a ray crosses the drawn surface; it also changes where the nearest piece
/// changes and across a piece's untrimmed zero set off its patch, where the sheet's
/// value is not small: a renderer accepts a sign change as a crossing only where the
/// sheet's value is below its hit threshold (march_ray.cpp, the page's preview.js).

#include <string>
#include <vector>

#include "implicitizer/scene/vec3.hpp"
#include "implicitizer/sdf/fast_sdf.hpp"

namespace implicitizer {

/// The side function of an approximated sheet (the file comment).
class SheetSide {
 public:
  /// One solid FastSdf per piece (q_k in its piece's frame box). Precondition: not empty.
  explicit SheetSide(std::vector<FastSdf> pieces);

  /// The estimate of the piece with the smallest |estimate| at p (float: the GLSL's
  /// arithmetic); its sign is the side.
  template <typename T>
  T evaluate(const Vec3<T>& p) const {
    T best = pieces_.front().evaluate<T>(p.x, p.y, p.z);
    for (std::size_t k = 1; k < pieces_.size(); ++k) {
      const T v = pieces_[k].evaluate<T>(p.x, p.y, p.z);
      if (std::abs(v) < std::abs(best)) best = v;
    }
    return best;
  }

  /// `float FUNCTION(vec3 p)` computing evaluate<float>, with its pieces as
  /// FUNCTION_piece<k>. Precondition: FUNCTION is a valid GLSL identifier.
  std::string to_glsl(const std::string& function) const;

 private:
  std::vector<FastSdf> pieces_;
};

}  // namespace implicitizer
