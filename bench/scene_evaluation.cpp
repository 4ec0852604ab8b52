/// \file
/// implicitizer-scene-bench: the time of one CompiledScene::evaluate<float> (what the
/// renderer calls per ray step), on two scenes built in code: five_spheres (a union
/// of translated spheres, as bench/scenes/five_spheres.json) and kinds (a smooth union
/// over a twist, a rotation, a finite repetition, a difference, a displacement, an
/// elongation, a symmetry and a scale: most node kinds). Each scene is evaluated at a
/// 40³ grid of points in [−2, 1.9]³, `reps` times (default 20); printed: the fastest
/// repetition's ns per evaluation, and a checksum of the values (equal across builds
/// when the arithmetic is). Written against only make_node, compile_scene and
/// evaluate, so the same file also compiles against an older tree (docs/benchmarks.md,
/// "Issue 17: compiled scenes with per-kind operations"). Not a test.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "implicitizer/scene/compiled_scene.hpp"

namespace {

using implicitizer::make_node;
using implicitizer::NodeKind;
using implicitizer::SceneNode;
using V = implicitizer::Vec3<double>;
using Parameters = std::vector<std::pair<std::string, implicitizer::ParameterValue>>;

SceneNode translated(V offset, SceneNode child) {
  return make_node(NodeKind::translate, Parameters{{"offset", offset}}, {std::move(child)});
}

SceneNode five_spheres() {
  const SceneNode s = make_node(NodeKind::sphere, Parameters{{"radius", 0.45}});
  return make_node(NodeKind::csg_union, {},
                   {translated({-0.8572, 0.6862, 2.0698}, s), translated({-0.4286, 0.3431, 1.0349}, s), s,
                    translated({0.4286, -0.3431, -1.0349}, s), translated({0.8572, -0.6862, -2.0698}, s)});
}

SceneNode kinds() {
  const SceneNode cone = make_node(NodeKind::cone, Parameters{{"angle", 0.5}, {"height", 1.0}});
  const SceneNode mirrored =
      make_node(NodeKind::symmetry, Parameters{{"axes", V{1, 0, 0}}},
                {translated({0.3, 0, 0}, make_node(NodeKind::scale, Parameters{{"factor", 0.5}}, {cone}))});
  return make_node(
      NodeKind::smooth_union, Parameters{{"k", 0.2}},
      {make_node(NodeKind::twist, Parameters{{"k", 0.5}},
                 {make_node(NodeKind::box, Parameters{{"size", V{0.4, 0.8, 0.4}}})}),
       translated({1.2, 0, 0}, make_node(NodeKind::rotate, Parameters{{"axis", V{1, 0, 0}}, {"angle", 0.7}},
                                         {make_node(NodeKind::torus, Parameters{{"major", 0.5}, {"minor", 0.15}})})),
       translated({0, 0, -1.2},
                  make_node(NodeKind::repeat_finite, Parameters{{"period", V{0.5, 0, 0.5}}, {"limit", V{2, 0, 1}}},
                            {make_node(NodeKind::sphere, Parameters{{"radius", 0.15}})})),
       make_node(NodeKind::csg_difference, {},
                 {translated({-1.2, 0, 0},
                             make_node(NodeKind::round_box, Parameters{{"size", V{0.5, 0.5, 0.5}}, {"radius", 0.1}})),
                  translated({-1.2, 0, 0}, make_node(NodeKind::cylinder, Parameters{{"radius", 0.25}}))}),
       make_node(
           NodeKind::displace, Parameters{{"amplitude", 0.03}, {"frequency", 8.0}},
           {make_node(NodeKind::capsule, Parameters{{"a", V{0, 1, 0}}, {"b", V{0.8, 1.4, 0.3}}, {"radius", 0.2}})}),
       translated({0, -1, 0.8}, make_node(NodeKind::elongate, Parameters{{"size", V{0.2, 0, 0.1}}}, {mirrored}))});
}

}  // namespace

int main(int argc, char** argv) {
  const int reps = argc > 1 ? std::atoi(argv[1]) : 20;
  std::vector<implicitizer::Vec3<float>> points;
  for (int i = 0; i < 40; ++i) {
    for (int j = 0; j < 40; ++j) {
      for (int k = 0; k < 40; ++k) points.push_back({-2 + 0.1f * i, -2 + 0.1f * j, -2 + 0.1f * k});
    }
  }
  for (const auto& [name, root] : {std::pair<const char*, SceneNode>{"five_spheres", five_spheres()},
                                   std::pair<const char*, SceneNode>{"kinds", kinds()}}) {
    const implicitizer::CompiledScene scene = implicitizer::compile_scene(root, {});
    double checksum = 0, best = 1e300;
    for (int r = 0; r < reps; ++r) {
      const auto start = std::chrono::steady_clock::now();
      for (const auto& p : points) checksum += scene.evaluate(p);
      const std::chrono::duration<double, std::nano> elapsed = std::chrono::steady_clock::now() - start;
      best = std::min(best, elapsed.count() / static_cast<double>(points.size()));
    }
    std::printf("%s %.1f ns/evaluation (checksum %.9g)\n", name, best, checksum);
  }
  return 0;
}
