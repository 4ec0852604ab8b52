#include "implicitizer/scene/shell.hpp"

#include "implicitizer/core/errors.hpp"
#include "node_operations.hpp"

namespace implicitizer {

std::string shell_glsl(const std::string& prefix) {
  return "float " + prefix + "_shell(float d, float t) {\n  return abs(d) - t;\n}\n";
}

// ---------------------------------------------------------------------------------
// The shell as a scene node: one child, thickness t in slot 0.

namespace {

// shell.hpp says why: 1-Lipschitz stays 1-Lipschitz, a bound becomes an outer bound,
// an outer bound bounds nothing; fast mode keeps 1-Lipschitz children exact and
// estimates the rest.
void classify_shell(NodeCompilation& c) {
  const NodeClass child = c.children_class();
  if (child == NodeClass::lipschitz) {
    c.out.node_class = NodeClass::lipschitz;
  } else if (!c.safe()) {
    c.out.node_class = NodeClass::estimate;
  } else if (child == NodeClass::bound) {
    c.out.node_class = NodeClass::outer_bound;
  } else {
    throw InputError("unsafe_operator", "in mode safe a shell needs a child that bounds its distance on both sides; " +
                                            c.path +
                                            ".child is only bounded outside (it is or uses a shell over a "
                                            "polynomial leaf or another mere bound)")
        .in_field(c.path + ".child");
  }
}

template <typename T>
T evaluate_shell(const SceneEvaluator<T>& e, const CompiledNode& n, const Vec3<T>& p) {
  return shell_value(e.child(n, 0, p), e.slots(n).scalar(0));
}

std::string emit_shell(SceneGlslWriter& w, const CompiledNode& n, const std::string& p) {
  w.require_helper("shell", shell_glsl(w.prefix()));
  const std::string d = w.child(n, 0, p);
  return w.value(w.call("shell", d + ", " + w.scalar(n, 0)), SceneGlslWriter::type(n));
}

}  // namespace

// The box: |d| ≤ t only where d ≤ t, so offset_child_box (node_operations.hpp).
const NodeOperations kShellOperations = {classify_shell, offset_child_box, evaluate_shell<float>,
                                         evaluate_shell<double>, emit_shell};

}  // namespace implicitizer
