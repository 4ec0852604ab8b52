// The node kind table: one row per NodeKind, in order, with unique type names.

#include "implicitizer/scene/scene_node.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace implicitizer {
namespace {

TEST(SceneNode, TableHasOneRowPerKindInOrder) {
  const auto& kinds = node_kinds();
  std::set<std::string_view> names;
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    EXPECT_EQ(static_cast<std::size_t>(kinds[i].kind), i);
    EXPECT_EQ(&node_kind_info(kinds[i].kind), &kinds[i]);
    EXPECT_TRUE(names.insert(kinds[i].type_name).second) << kinds[i].type_name;
    EXPECT_EQ(find_node_kind(kinds[i].type_name), &kinds[i]);
    for (const ParameterSpec& p : kinds[i].parameters) {
      // Counts shape the code: they can never be uniforms.
      if (p.type == ParameterType::count) {
        EXPECT_FALSE(p.uniformable) << p.name;
      }
    }
  }
  EXPECT_EQ(find_node_kind("no_such_kind"), nullptr);
  EXPECT_EQ(find_node_kind("csg_union"), nullptr);  // the JSON name is "union"
  EXPECT_NE(find_node_kind("union"), nullptr);
}

TEST(SceneNode, SetReplacesAndMakeNodeBuilds) {
  SceneNode node = make_node(NodeKind::sphere, {{"radius", 1.0}});
  node.set("radius", 2.0).set("other", Vec3<double>{1, 2, 3});
  ASSERT_EQ(node.parameters.size(), 2u);
  EXPECT_EQ(node.parameters[0].second.value.x, 2.0);
  EXPECT_FALSE(node.parameters[0].second.is_vector);
  EXPECT_TRUE(node.parameters[1].second.is_vector);
}

}  // namespace
}  // namespace implicitizer
