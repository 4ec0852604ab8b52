// The reference distance (tests/sdf/reference_distance.hpp) against closed forms, and
// the distance estimates of lib/sdf against the reference.

#include "sdf/reference_distance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <random>
#include <string>

#include "implicitizer/sdf/enclosure.hpp"
#include "implicitizer/sdf/fast_sdf.hpp"
#include "implicitizer/sdf/safe_sdf.hpp"
#include "sdf/sdf_support.hpp"

namespace implicitizer {
namespace {

using testing::ClosedForm;
using testing::Point3;
using testing::ReferenceDistance;

// A public surface of ../shared/bench with its implicit equation and parametrization.
struct PublicSurface {
  std::string name;
  Parametrization parametrization;
  Polynomial implicit;
};

const std::vector<PublicSurface>& public_surfaces() {
  static const std::vector<PublicSurface> surfaces = [] {
    std::vector<PublicSurface> out;
    for (const testing::Surface& s :
         testing::read_surfaces(std::string(IMPLICITIZER_SHARED_DIR) + "/bench/surfaces_public.json")) {
      Parametrization p = parse_parametrization(s.x, s.y, s.z);
      const Polynomial f = implicitize(p).implicit;
      out.push_back({s.name, std::move(p), f});
    }
    return out;
  }();
  return surfaces;
}

const PublicSurface& public_surface(const std::string& name) {
  for (const PublicSurface& s : public_surfaces()) {
    if (s.name == name) return s;
  }
  throw std::runtime_error("no public surface " + name);
}

// The reference built the general way (cloud, descents and Newton, the
// parametrization's samples included) agrees with the closed form of the same
// surface at uniform and near-surface points, and is never below it (it is an upper
// bound up to 1e-12·h). Tolerance 1e-11 relative to max(D, 1e-3·h); measured at
// most 3e-13 here and 7.1e-13 over the bench's 2000 points (docs/sdf.md).
TEST(ReferenceDistance, AgreesWithClosedFormsOfThePublicSurfaces) {
  const std::map<std::string, ClosedForm::Kind> expected = {{"plane", ClosedForm::Kind::plane},
                                                            {"unit_sphere", ClosedForm::Kind::sphere},
                                                            {"cylinder_rational", ClosedForm::Kind::cylinder},
                                                            {"cone_rational", ClosedForm::Kind::cone},
                                                            {"torus_R2_r1", ClosedForm::Kind::torus}};
  for (const auto& [name, kind] : expected) {
    const PublicSurface& s = public_surface(name);
    const SceneBox box = testing::public_surface_box(name);
    const ReferenceDistance reference = ReferenceDistance::build(s.implicit, &s.parametrization, box);
    ASSERT_TRUE(reference.closed_form().has_value()) << name;
    EXPECT_EQ(reference.closed_form()->kind, kind) << name;
    const double h = reference.box().half_extent();
    double worst_refined = 0, worst_cloud = 0;
    for (const Point3& p : testing::accuracy_samples(reference, 400, 11)) {
      const double exact = reference.closed_form()->distance(p);
      const double refined = reference.refined_distance(p);
      const double cloud = reference.cloud_distance(p);
      const double scale = std::max(exact, 1e-3 * h);
      EXPECT_GE(refined, exact - 1e-12 * h) << name << " at " << p[0] << " " << p[1] << " " << p[2];
      EXPECT_LE(refined - exact, 1e-11 * scale) << name << " at " << p[0] << " " << p[1] << " " << p[2];
      worst_refined = std::max(worst_refined, std::fabs(refined - exact) / scale);
      worst_cloud = std::max(worst_cloud, (cloud - exact) / h);
    }
    std::cout << name << " (" << reference.closed_form()->describe() << ", " << reference.line_points()
              << " line roots, " << reference.parameter_points() << " parameter points, "
              << reference.zero_lines().size() << " zero lines): refined worst relative error " << worst_refined
              << ", cloud alone worst excess " << worst_cloud << "·h\n";
  }
}

// The closed forms themselves, at points where the answer is known by hand.
TEST(ReferenceDistance, ClosedFormsAtHandPickedPoints) {
  const testing::DistanceBox box = testing::DistanceBox::from_scene_box(SceneBox::default_box());
  const auto torus = testing::recognise_closed_form(testing::parse_xyz("(x^2+y^2+z^2+3)^2-16*(x^2+y^2)"),
                                                    testing::DistanceBox{{-4, -4, -4}, {4, 4, 4}});
  ASSERT_TRUE(torus.has_value());
  EXPECT_DOUBLE_EQ(torus->distance({0, 0, 0}), 1.0);    // the hole's centre: R − r
  EXPECT_DOUBLE_EQ(torus->distance({2, 0, 0.5}), 0.5);  // inside the tube
  const auto cylinder = testing::recognise_closed_form(testing::parse_xyz("x^2+y^2-1"), box);
  ASSERT_TRUE(cylinder.has_value());
  EXPECT_DOUBLE_EQ(cylinder->distance({0, 0, 3}), std::hypot(1.0, 1.0));  // beyond the clip z = 2
  const auto cone = testing::recognise_closed_form(testing::parse_xyz("x^2+y^2-z^2"), box);
  ASSERT_TRUE(cone.has_value());
  EXPECT_NEAR(cone->distance({1, 0, 0}), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(cone->distance({0, 0, 3}), std::sqrt(4.5), 1e-15);  // (1.5, 1.5) in the meridian
  const auto plane = testing::recognise_closed_form(testing::parse_xyz("x-y-z"), box);
  ASSERT_TRUE(plane.has_value());
  EXPECT_NEAR(plane->distance({1, 0, 0}), 1 / std::sqrt(3.0), 1e-15);
  // On the plane but outside the box: the nearest point is (2, 0, 2), on the
  // polygon's edge in the face x = 2.
  EXPECT_NEAR(plane->distance({3, 0, 3}), std::sqrt(2.0), 1e-15);
  // Not recognised: a sphere that leaves the box, an ellipsoid.
  EXPECT_FALSE(testing::recognise_closed_form(testing::parse_xyz("x^2+y^2+z^2-9"), box).has_value());
  EXPECT_FALSE(testing::recognise_closed_form(testing::parse_xyz("x^2+2*y^2+z^2-1"), box).has_value());
}

// On singular surfaces the zero set holds whole axis lines: Steiner's surface
// (its three axes) and Whitney's umbrella (its handle x = y = 0). The reference finds
// them as zero lines and measures distance to them exactly.
TEST(ReferenceDistance, FindsTheAxesInSingularZeroSets) {
  const PublicSurface& steiner = public_surface("steiner_roman");
  const ReferenceDistance r1 = ReferenceDistance::build(steiner.implicit, &steiner.parametrization,
                                                        testing::public_surface_box("steiner_roman"));
  EXPECT_EQ(r1.zero_lines().size(), 3u);
  // (0.9, 0.05, 0): on the x axis' whisker (not in the image), 0.05 away.
  EXPECT_NEAR(r1.distance({0.9, 0.05, 0}), 0.05, 1e-12);
  const PublicSurface& whitney = public_surface("whitney_umbrella");
  const ReferenceDistance r2 = ReferenceDistance::build(whitney.implicit, &whitney.parametrization,
                                                        testing::public_surface_box("whitney_umbrella"));
  ASSERT_GE(r2.zero_lines().size(), 1u);
  // Below the umbrella (z < 0) the zero set is the handle alone.
  EXPECT_NEAR(r2.distance({0.03, -0.04, -1}), 0.05, 1e-12);
}

// A singular curve off the grid: Whitney's umbrella x² − y²z in a box whose grid
// lines miss its handle (x = y = 0, z < 0, where F = x² + y²|z| touches 0 without a
// sign change and no real parameter maps). No line root and no parameter sample
// lies on the handle; the extrema of F along the lines near it seed Gauss–Newton on
// ∇F = 0, and the distance below the umbrella is the distance to the axis.
TEST(ReferenceDistance, FindsSingularCurvesOffTheGrid) {
  const PublicSurface& whitney = public_surface("whitney_umbrella");
  // Centre (0.1, 0.1, 0): grid coordinates −1.9 + k/16, never 0 in x or y.
  const SceneBox box = testing::box_of("-1.9", "-1.9", "-2", "2.1", "2.1", "2");
  const ReferenceDistance reference = ReferenceDistance::build(whitney.implicit, &whitney.parametrization, box);
  EXPECT_TRUE(reference.zero_lines().empty());
  ASSERT_FALSE(reference.singular_points().empty());
  std::mt19937 random(3);
  std::uniform_real_distribution<double> offset(-0.2, 0.2), depth(-1.9, -0.5);
  double worst = 0;
  for (int i = 0; i < 100; ++i) {
    const Point3 p = {offset(random), offset(random), depth(random)};
    // The umbrella's sheet has z >= 0, farther than |z| >= 0.5 > the axis' 0.29.
    const double axis = std::hypot(p[0], p[1]);
    EXPECT_NEAR(reference.distance(p), axis, 1e-9 * axis) << p[0] << " " << p[1] << " " << p[2];
    EXPECT_GT(reference.cloud_distance(p) - axis, -1e-12);
    worst = std::max(worst, std::fabs(reference.distance(p) - axis) / axis);
  }
  std::cout << "Whitney's handle off the grid: " << reference.singular_points().size()
            << " singular points, worst relative error " << worst << '\n';
}

// Mode fast on the unit sphere, where everything is known: with r = |p|,
// F/|∇F| = (r² − 1)/(2r) and D = |r − 1|, so |v|/D = (r + 1)/(2r): above 1 inside
// (where fast overshoots), below 1 outside, 1 on the surface. The measured
// statistics must be the theory's.
TEST(FastSdfAccuracy, UnitSphereRatiosMatchTheory) {
  const Polynomial f = testing::parse_xyz("x^2+y^2+z^2-1");
  const FastSdf sdf = FastSdf::build(f, SceneBox::default_box());
  const ReferenceDistance reference = ReferenceDistance::build(f, nullptr, SceneBox::default_box());
  ASSERT_TRUE(reference.closed_form().has_value());
  const double h = reference.box().half_extent();
  std::vector<double> values, distances, theory_values;
  for (const Point3& p : testing::accuracy_samples(reference, 2000, 7)) {
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const double distance = reference.distance(p);
    EXPECT_NEAR(distance, std::fabs(r - 1), 1e-15);
    const double value =
        sdf.evaluate<float>(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
    // F/|∇F|, clipped to the box as fast mode clips it (docs/sdf.md §3).
    const double theory = std::max((r * r - 1) / (2 * r), testing::signed_box_distance(sdf.frame(), p[0], p[1], p[2]));
    // fp32: 3e-5 relative as in fast_sdf_test.cpp, plus the 1e-6·h floor.
    EXPECT_NEAR(value, theory, 3e-5 * std::fabs(theory) + 1e-6 * h) << r;
    values.push_back(value);
    theory_values.push_back(theory);
    distances.push_back(distance);
  }
  const testing::EstimateStatistics measured = testing::summarise_estimates(values, distances, h);
  const testing::EstimateStatistics theory = testing::summarise_estimates(theory_values, distances, h);
  std::cout << "fast on the unit sphere: over " << measured.over << "/" << measured.points << " (theory " << theory.over
            << "), median |v|/D " << measured.median_ratio << " (theory " << theory.median_ratio << "), 5th percentile "
            << measured.p5_ratio << " (theory " << theory.p5_ratio << "), max " << measured.max_ratio << " (theory "
            << theory.max_ratio << ")\n";
  // Inside the sphere (about half the shell points and 6.5 % of the uniform ones)
  // fast overshoots by (r + 1)/(2r) - 1 >= 1e-3 at the shell's smallest offset.
  EXPECT_GT(measured.over, measured.points / 5);
  EXPECT_NEAR(static_cast<double>(measured.over), static_cast<double>(theory.over), 2);
  EXPECT_NEAR(measured.median_ratio, theory.median_ratio, 3e-5 * theory.median_ratio);
  EXPECT_NEAR(measured.p5_ratio, theory.p5_ratio, 3e-5 * theory.p5_ratio);
  // The smallest ratio is at the box's corners, r = 2√3: (r + 1)/(2r) > 0.64.
  EXPECT_GT(measured.p5_ratio, 0.6);
}

// Mode safe never exceeds the true distance: at 400 points per public surface (half
// uniform, half 1e-3..1e-1 of the box's size from the surface), in its box, the
// fp32 bound is at most the reference (which is an upper bound of D up to
// 1e-12·h, tight where measured above), within EstimateStatistics' margin of
// 1e-6 relative plus 1e-7·h. The bench runs the same with more points.
TEST(SafeSdfAccuracy, NeverExceedsTheReferenceOnThePublicSurfaces) {
  for (const PublicSurface& s : public_surfaces()) {
    const SceneBox box = testing::public_surface_box(s.name);
    const ReferenceDistance reference = ReferenceDistance::build(s.implicit, &s.parametrization, box);
    const SafeSdf safe = SafeSdf::build(s.implicit, box);
    const double h = reference.box().half_extent();
    std::vector<double> values, distances;
    for (const Point3& p : testing::accuracy_samples(reference, 400, 23)) {
      const float value =
          safe.evaluate<float>(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
      const double distance = reference.distance(p);
      EXPECT_LE(std::fabs(value), distance * (1 + testing::EstimateStatistics::kOverRelative) +
                                      testing::EstimateStatistics::kOverAbsolute * h)
          << s.name << " at (" << p[0] << ", " << p[1] << ", " << p[2] << ")";
      values.push_back(value);
      distances.push_back(distance);
    }
    const testing::EstimateStatistics stats = testing::summarise_estimates(values, distances, h);
    EXPECT_EQ(stats.over, 0u) << s.name;
    EXPECT_EQ(stats.points, 400u) << s.name;
    std::cout << s.name << ": safe over " << stats.over << "/" << stats.points << ", median |v|/D "
              << stats.median_ratio << ", 5th percentile " << stats.p5_ratio << ", max " << stats.max_ratio << '\n';
  }
}

// Sheets (shape sheet): at the same points, the safe sheet is >= 0, at least the
// magnitude of the safe solid (it takes the radius where the solid takes the smaller
// of the radius and the distance to the faces), and never above the reference
// distance; the fast sheet is >= 0 and the magnitude of the fast solid wherever F >= 0
// or the point is outside the box.
TEST(SafeSdfAccuracy, SheetsAreNonNegativeLowerBoundsOnThePublicSurfaces) {
  for (const PublicSurface& s : public_surfaces()) {
    const SceneBox box = testing::public_surface_box(s.name);
    const ReferenceDistance reference = ReferenceDistance::build(s.implicit, &s.parametrization, box);
    const SafeSdf solid = SafeSdf::build(s.implicit, box);
    const SafeSdf sheet = SafeSdf::build(s.implicit, box, Budget(), SdfShape::sheet);
    const FastSdf fast = FastSdf::build(s.implicit, box, Budget(), SdfShape::sheet);
    const double h = reference.box().half_extent();
    std::size_t positive = 0, points = 0;
    for (const Point3& p : testing::accuracy_samples(reference, 200, 29)) {
      const float x = static_cast<float>(p[0]), y = static_cast<float>(p[1]), z = static_cast<float>(p[2]);
      const float value = sheet.evaluate<float>(x, y, z);
      const std::string where =
          s.name + " at (" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) + ")";
      EXPECT_GE(value, 0.0f) << where;
      EXPECT_GE(value, std::fabs(solid.evaluate<float>(x, y, z))) << where;
      EXPECT_LE(value, reference.distance(p) * (1 + testing::EstimateStatistics::kOverRelative) +
                           testing::EstimateStatistics::kOverAbsolute * h)
          << where;
      EXPECT_GE(fast.evaluate<float>(x, y, z), 0.0f) << where;
      if (value > 0) ++positive;
      ++points;
    }
    EXPECT_GT(positive, points / 2) << s.name;
  }
}

// Shape auto on the twelve public surfaces in their boxes (public_surface_box): only
// the closed ones inside their boxes (the sphere, the torus) are solids; every open
// surface, and Steiner's surface (its axes reach the faces of [−1, 1]³), is a sheet.
// Prints how long each decision takes (docs/sdf.md, "Shapes").
TEST(SdfShapes, AutoOnThePublicSurfaces) {
  for (const PublicSurface& s : public_surfaces()) {
    const SceneBox box = testing::public_surface_box(s.name);
    const SceneFrame frame = make_scene_frame(box);
    std::vector<std::pair<Rational, Rational>> cube;
    for (std::size_t i = 0; i < 3; ++i) {
      cube.emplace_back(frame.centre[i] - Rational(1) / frame.scale, frame.centre[i] + Rational(1) / frame.scale);
    }
    const auto start = std::chrono::steady_clock::now();
    const Enclosure e = decide_enclosure(s.implicit, cube);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const bool closed = s.name == "unit_sphere" || s.name == "torus_R2_r1";
    EXPECT_EQ(e.shape, closed ? SdfShape::solid : SdfShape::sheet) << s.name << ": " << e.reason;
    std::cout << s.name << " (degree " << s.implicit.total_degree() << "): " << to_string(e.shape) << " in " << ms
              << " ms: " << e.reason << '\n';
  }
}

}  // namespace
}  // namespace implicitizer
