#include "help.hpp"

namespace implicitizer::cli {

const char* const kGeneralHelp = R"(usage: implicitizer COMMAND [OPTIONS] [ARGUMENTS]

Exact implicitization, Groebner bases and resultants over the rationals.

commands:
  implicitize   the implicit equation of a parametrized surface
  groebner      the reduced Groebner basis of an ideal (or an elimination ideal)
  resultant     the resultant of two polynomials with respect to one variable
  sdf           a GLSL distance function of a surface, patch, curve or scene
  render        a PNG preview of a surface, patch, curve or scene
  help [CMD]    this text, or the help of one command
  --version     the version

  implicitizer implicitize --x E --y E [--z E] [--params s,t]
               [--method auto|groebner|resultant|interpolation] [--timeout SECONDS] [--json]
  implicitizer groebner [--vars x,y,z] [--order lex|grlex|grevlex] [--weights 1,2,3]
               [--eliminate s,t] [--timeout SECONDS] [--json] F [F ...]
  implicitizer resultant --var t [--timeout SECONDS] [--max-terms N] [--max-memory SIZE] [--json] F G
  implicitizer sdf (--implicit E | --x E --y E [--z E] [--params s,t] | --scene FILE.json)
               [--shape auto|sheet|solid] [--domain s0,s1[,t0,t1]] [--mode fast|safe]
               [--box x0,y0,z0,x1,y1,z1] [--name NAME] [--tolerance EPS] [--eval FILE] [--json]
  implicitizer render (--implicit E | --x E --y E [--z E] [--params s,t] | --scene FILE.json)
               [--shape ...] [--domain ...] [--tolerance EPS]
               [--method sphere|enhanced|newton|forward_newton|exact] [--mode fast|safe] [--size WxH]
               [--aa N] [--eye x,y,z] [--target x,y,z] [--box ...] [--timeout S] -o FILE.png [--json]
  implicitize and groebner also take --strategy auto|normal|sugar,
  --criteria gm|seed|product|none, --max-terms N, --max-memory SIZE

syntax: numbers are exact (0.25, 1e-30); + - * / ^ (** = ^); ^ binds tightest, so
  -x^2 = -(x^2); 2x is 2*x and binds tighter than * and /, so 1/2x = 1/(2x);
  two names need a *; x^2^3 is refused; exponents are integer literals.

exit status: 0 success, 1 internal error, 2 usage error, 3 invalid input,
  4 no single implicit equation, 5 time or size limit.
See docs/cli.md for every flag and error code.
)";

const char* const kImplicitizeHelp = R"(usage: implicitizer implicitize --x E --y E [--z E] [OPTIONS]

Prints the implicit equation F(x,y,z) = 0 of the surface x = E, y = E, z = E, as one
line: expanded, grevlex x > y > z, integer coefficients with gcd 1, positive leading
coefficient. Without --z, the implicit curve F(x,y) = 0 of the plane
parametrization. The expressions may be rational functions of the parameters.

options:
  --x E, --y E          the parametrization (required)
  --z E                 its third coordinate (omit it for a plane curve)
  --params s,t          the parameters (default: every identifier other than x, y, z,
                        in order of first appearance, --x first)
  --method M            auto (default): interpolation when the degree is at most 4;
                        else, after a head start for Buchberger, the resultant
                        without base points (interpolation for triangular patches
                        up to degree 9), else interpolation (docs/algorithms.md
                        has the rule); groebner: Buchberger;
                        resultant: the auxiliary resultant, or exit 4 (base_points);
                        interpolation: the kernel of evaluated monomials modulo
                        primes (any parametrization, base points or not)
  --modular             the groebner route modulo primes (the equation proven by
                        substitution and minimality; Buchberger over Q where not)
  --timeout SECONDS     wall-time limit, > 0 (default: none)
  --max-terms N         largest number of terms of any intermediate polynomial (default 0 = none)
  --max-memory SIZE     memory the computation may hold: 512 (MiB), 512M, 2G (default: none);
                        beyond it, exit 5 with memory_limit_exceeded
  --strategy S          S-pair selection: auto (default: sugar for elimination
                        orders, normal otherwise), normal or sugar
  --criteria C          gm (default): product criterion + Gebauer-Moller chain criterion
                        seed: product criterion + Buchberger's chain criterion
                              (Theorem 1.6 of the seed thesis)
                        product: product criterion only;  none: no criterion
  --json                print the JSON object POST /v1/implicitize returns; errors as
                        {"error": {...}} on stdout too
  -h, --help            this text

exit status: 0 success, 2 usage error, 3 invalid input, 4 the image is a curve or a
point (no single equation; the generators go to stderr), 5 time or size limit.
)";

const char* const kGroebnerHelp = R"(usage: implicitizer groebner [OPTIONS] F [F ...]

Prints the reduced Groebner basis of the ideal generated by the polynomials F, one
monic element per line, by increasing leading monomial (a zero ideal prints 0).

options:
  --vars x,y,z          the ring's variables, largest first (default: the identifiers
                        of the polynomials in order of first appearance)
  --order O             lex, grlex or grevlex (default grevlex)
  --weights 1,2,3       weighted order: weighted degree first, then --order breaks ties
                        (one weight per variable, in [0, 1024])
  --eliminate s,t       print the generators of the elimination ideal instead (the
                        ideal intersected with the ring of the other variables, under
                        --order); the basis is then computed in an elimination order
                        for s,t (docs/cli.md); --json shows both
  --method M            auto (default): Buchberger over Q for about 5 ms of its work,
                        then f4;
                        buchberger; modular: modulo primes, lifted, proven over Q;
                        f4: the same with F4 modulo each prime
  --modular             the same as --method modular
  --proof P             exact (default): the modular routes prove their basis over Q;
                        random_primes: they skip the proof and check the basis modulo
                        2 random primes instead: faster, NOT proven (a wrong basis
                        passes with probability below 10^-19 unless an integer fixed
                        by the ideal has over 10^9 bits; docs/algorithms.md); a note
                        on stderr says so, and --json has "proven": false
  --timeout SECONDS     wall-time limit, > 0 (default: none)
  --max-terms N         largest number of terms of any intermediate polynomial (default 0 = none)
  --max-memory SIZE     memory the computation may hold: 512 (MiB), 512M, 2G (default: none);
                        beyond it, exit 5 with memory_limit_exceeded
  --strategy S          auto (default), normal or sugar
  --criteria C          gm (default), seed, product or none (see implicitize --help)
  --json                print the JSON object POST /v1/groebner returns
  -h, --help            this text

A polynomial may start with '-': only words starting with '--' are options ('--'
ends them).
exit status: 0 success, 2 usage error, 3 invalid input, 5 time or size limit.
)";

const char* const kResultantHelp = R"(usage: implicitizer resultant --var t [OPTIONS] F G

Prints Res_t(F, G), the resultant of F and G as polynomials in t with coefficients
in the other variables (the determinant of their Sylvester matrix), on one line:
exact rational coefficients, terms in grevlex order on the variables of F and G in
order of first appearance. It is 0 exactly when F and G have a common factor
involving t (or one of them is 0); c^deg G when F = c does not involve t.

options:
  --var t               the variable to eliminate (required); it must occur in F or G
  --timeout SECONDS     wall-time limit, > 0 (default: none)
  --max-terms N         largest number of terms of any intermediate polynomial (default 0 = none)
  --max-memory SIZE     memory the computation may hold: 512 (MiB), 512M, 2G (default: none);
                        beyond it, exit 5 with memory_limit_exceeded
  --json                print the JSON object POST /v1/resultant returns
  -h, --help            this text

A polynomial may start with '-': only words starting with '--' are options ('--'
ends them).
exit status: 0 success, 2 usage error, 3 invalid input (parse error, unknown
variable), 5 time or size limit.
)";

const char* const kSdfHelp =
    R"(usage: implicitizer sdf (--implicit E | --x E --y E [--z E] | --scene FILE.json) [OPTIONS]

Prints GLSL source defining float NAME_sdf(vec3 p) (vec2 p for a plane curve): the
distance function of a surface E = 0, of a parametric patch X(D), of a plane curve
or of a scene, evaluated in fp32 in a frame centred and scaled to the box
(docs/sdf.md). Every input compiles as a scene: the uniforms and only the helpers
its nodes use come before NAME_sdf. It compiles as GLSL ES 3.00 and as GLSL 330.

options:
  --implicit E          the polynomial F(x, y, z); without z, F(x, y): a plane curve
  --x E --y E [--z E]   a parametric surface, or without --z a plane curve, in its
                        parameters (--params s,t: their order)
  --scene FILE.json     a scene: a JSON tree of primitives, implicit and parametric
                        leaves and operators (docs/sdf.md, "Scenes")
                        (exactly one of the three)
  --shape auto|sheet|solid
                        solid: F <= 0 clipped to the box, negative inside; sheet:
                        the surface itself, >= 0, 0 on it; auto (default): solid
                        only where the surface encloses a region inside its box
                        (--json says which was picked). A scene's leaves carry
                        their own "shape"
  --domain s0,s1[,t0,t1]
                        the parameter domain of --x --y [--z], exact numbers with
                        lo < hi (default: docs/sdf.md, "Patches")
  --tolerance EPS       model the patch of --x --y --z (a bounded domain) within
                        EPS x its box's diagonal, both ways, 0 < EPS <= 0.5: the
                        fewer GLSL lines of low-degree pieces and the exact
                        equation (--json reports which, with degree, pieces, GLSL
                        lines and the bounds reached); default: the exact equation
  --mode fast|safe      fast: F/|grad F|, first order, not a bound (default); safe: a
                        proven lower bound of the distance (sphere tracing never
                        crosses the surface; slower, 0 within fp32's resolution)
  --box x0,y0,z0,x1,y1,z1
                        the box, exact numbers (default -2,-2,-2,2,2,2; a curve's
                        is x0,y0,x1,y1; a patch's default is fitted to it)
  --name NAME           function NAME_sdf (default surface): [A-Za-z_][A-Za-z0-9_]*,
                        at most 64 characters, not gl nor a gl_ prefix (gl_sdf is
                        reserved), no __, no trailing _, not a GLSL keyword
  --eval FILE           instead of the GLSL, print the value at each point of FILE
                        (- : standard input), one per line (%.9g): lines "x y z"
                        ("x y" for a curve), blank lines and # comments skipped;
                        computed in C++ float, as the GLSL computes it; streamed
                        (a file is checked whole first; - prints as it reads)
  --json                print the JSON object POST /v1/sdf returns (with --eval,
                        on the first line, the values after it)
  -h, --help            this text

exit status: 0 success, 2 usage error (also: a scene or point file that cannot be
read), 3 invalid input (parse error, unknown variable, constant polynomial,
invalid_box, invalid_domain, invalid_name, invalid_point: a malformed line of
--eval's file, named by its number; degree_too_high: mode safe and terms beyond
fp32's range; for scenes invalid_json, invalid_scene, unknown_node_type,
missing_parameter, invalid_value, name_collision, unsafe_operator,
repetition_overlap, unbounded_child, scene_too_large, unbounded_patch,
no_single_equation: a parametric leaf whose image is not a surface;
invalid_tolerance: --tolerance not in (0, 0.5], or not a parametric surface), 4 no
single equation (a parametrization whose image is not a surface or curve), or
tolerance_not_met (the best bound reached is printed), 5 time or size limit.
)";

const char* const kRenderHelp =
    R"(usage: implicitizer render (--implicit E | --x E --y E [--z E] | --scene FILE.json) -o FILE.png [OPTIONS]

Draws a preview of the surface E = 0, of a parametric patch, of a plane curve (in
the plane) or of a scene into a PNG: rays marched through the same distance
function the GLSL of `implicitizer sdf` computes (evaluated in fp32 on the CPU),
shaded with Blinn-Phong, soft shadows and ambient occlusion (docs/render.md).

options:
  --implicit E          the polynomial F(x, y, z) (without z: a plane curve)
  --x E --y E [--z E]   a parametric surface or (no --z) curve instead (--params s,t:
                        their order)
  --scene FILE.json     a scene instead (docs/sdf.md, "Scenes")
  --shape auto|sheet|solid, --domain s0,s1[,t0,t1], --tolerance EPS
                        as for sdf
  -o, --output FILE     the PNG to write (required)
  --method M            sphere (default): sphere tracing; enhanced: over-relaxed
                        sphere tracing, as safe as sphere; newton, forward_newton:
                        Newton marching with checked steps, as safe as sphere; exact:
                        the first root of the polynomial on each ray (implicit and
                        parametric surfaces only)
  --mode fast|safe      the distance function: fast F/|grad F| (default) or the safe
                        bound (sphere tracing never crosses the surface)
  --size WxH            image size in pixels (default 256x256)
  --aa N                N x N samples per pixel, 1 to 8 (default 2)
  --eye x,y,z           the camera (default: box centre + (3,3,5) x box half side / 2)
  --target x,y,z        the look-at point (default: the box centre)
  --box x0,y0,z0,x1,y1,z1
                        the scene box, exact numbers (default -2,-2,-2,2,2,2)
  --precision float|double
                        the arithmetic of the distance function (default float,
                        what a GPU computes)
  --threads N           render threads (default: one per core)
  --timeout SECONDS     stop (exit 5) when the render takes longer
  --json                print {"width", "height", "method", "mode", "rays",
                        "mean_evaluations", "max_evaluations", "out_of_steps", "hits",
                        "elapsed_ms", ...} (what POST /v1/render answers with
                        "format": "json", without the PNG)
  -h, --help            this text

limits: width and height 1 to 4096, width x height x aa^2 at most 4194304 rays.

exit status: 0 success, 2 usage error (also: a scene file that cannot be read, an
output file that cannot be written), 3 invalid input (the errors of sdf, and
invalid_size, render_too_large, invalid_camera, method_not_applicable: exact on a
scene that is not one polynomial leaf, or an approximation), 4 no single equation
(a parametrization whose image is not a surface or curve) or tolerance_not_met, 5
time limit.
)";

}  // namespace implicitizer::cli
