#!/usr/bin/env node
// Writes clients/web/examples.json, the web client's examples menu, from the public
// benchmark surfaces (../shared/bench/surfaces_public.json) and Singular's implicit
// equation of each (../shared/bench/expected/NAME.txt, shown when the page is in
// "implicit equation" mode).
//
//   node scripts/make-web-examples.mjs            # (re)write clients/web/examples.json
//   node scripts/make-web-examples.mjs --check    # exit 1 if it is out of date
//
// Why a committed file: the server serves clients/web as it is in the source tree
// (`make run` passes --static clients/web) and nothing outside it, and shared/ is not
// part of this repository; a copy made at build time would have to be written into
// the source tree anyway. So the file is generated once, committed, and the browser
// test (tests/web) runs `buildExamples()` to check that it still matches shared/.
//
// Each surface gets the box the benchmarks and the gallery frame it in
// (tests/sdf/reference_distance.hpp `public_surface_box`, scripts/render-examples.sh):
// the page frames the implicit equation with it. The parametric form is drawn as the
// patch X(D) over its domain D, in a box the server fits to the patch (docs/sdf.md,
// "Patches"); open surfaces get a domain that shows their shape (DOMAINS), closed
// rational ones (sphere, torus, Steiner's surface) keep the default, the whole plane.
// The page's own examples (EXTRA_EXAMPLES): a bicubic patch, a plane curve, and three
// surfaces as textbooks write them, in cos/sin and cosh/sinh (issue 20), which the
// server makes rational (docs/api.md, "substitution"). An example names its parameters
// (`parameters`, the page's parameters field) when they are not s, t.
import fs from 'node:fs';
import path from 'node:path';
import process from 'node:process';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
export const examplesPath = path.join(root, 'clients', 'web', 'examples.json');
export const defaultSharedDir = path.join(root, '..', 'shared');

// The box [x0, y0, z0, x1, y1, z1] of a public surface (public_surface_box).
function boxOf(name) {
  const cube = (cx, half) => [cx - half, -half, -half, cx + half, half, half];
  if (name === 'torus_R2_r1' || name === 'enneper') return cube(0, 4);
  if (name === 'steiner_roman') return cube(0, 1);
  if (name === 'biquadratic_patch') return cube(2, 4);
  return cube(0, 2);
}

// The parameter domain s0, s1, t0, t1 (exact numbers as text) of a public surface
// whose default domain ([0, 1]^2 for a polynomial or unbounded parametrization) shows
// too little of it; absent: the default.
const DOMAINS = {
  plane: ['-1', '1', '-1', '1'],
  elliptic_paraboloid: ['-1', '1', '-1', '1'],
  hyperbolic_paraboloid: ['-1', '1', '-1', '1'],
  whitney_umbrella: ['-1', '1', '-1', '1'],
  // s = tan(θ/2): [-2, 2] is θ within ±127°, three quarters of the circle, so both
  // sides of the sheet show; t is the height.
  cylinder_rational: ['-2', '2', '-1', '1'],
  cone_rational: ['-2', '2', '-1', '1'],
  enneper: ['-3/2', '3/2', '-3/2', '3/2'],
  bicubic_graph: ['-1', '1', '-1', '1'],
};

// Examples that are not benchmark surfaces, with their implicit equations as
// `implicitizer implicitize --x X --y Y [--z Z] [--params P]` computes them (verified:
// the parametrization substituted gives 0). The trigonometric sphere and torus keep
// the default domain (every angle but π, where tan(θ/2) is infinite: the rational form's
// whole plane); the hyperboloid's domain is u in [-1, 1] and the angle v in [-5/2, 5/2]
// radians (radians are exact numbers like any other; π is not one, so a closed circle
// of angles cannot be typed, and the default domain of an unbounded patch would show
// only a corner of it). Not wider: tv = tan(v/2) grows fast towards v = ±π (14 at
// v = 3), and so do the patch's cover and GLSL. At the page's default tolerance the
// exact equation (degree 2) is the shorter GLSL and is kept.
const EXTRA_EXAMPLES = [
  {
    name: 'bicubic_patch',
    label: 'Bicubic patch',
    x: 's*(1+t^2)/2',
    y: 't',
    z: 's^3*t-s*t^3',
    degree: 8,
    domain: ['-1', '1', '-1', '1'],
    box: [-1, -1, -1, 1, 1, 1],
    implicit: '2*x*y^7+y^6*z+4*x*y^5+3*y^4*z-8*x^3*y+2*x*y^3+3*y^2*z+z',
    group: 'page',
  },
  {
    name: 'lemniscate',
    label: 'Lemniscate of Bernoulli (plane curve)',
    x: 't*(1+t^2)/(1+t^4)',
    y: 't*(1-t^2)/(1+t^4)',
    z: '',
    parameters: ['t'],
    degree: 4,
    box: [-1.25, -0.75, 1.25, 0.75],
    implicit: 'x^4+2*x^2*y^2+y^4-x^2+y^2',
    group: 'page',
  },
  {
    name: 'sphere_trig',
    label: 'Unit sphere in cos/sin',
    x: 'cos(u)*cos(v)',
    y: 'cos(u)*sin(v)',
    z: 'sin(u)',
    parameters: ['u', 'v'],
    degree: 2,
    box: [-2, -2, -2, 2, 2, 2],
    implicit: 'x^2+y^2+z^2-1',
    group: 'page',
  },
  {
    name: 'torus_trig',
    label: 'Torus in cos/sin, R = 2, r = 1',
    x: '(2+cos(v))*cos(u)',
    y: '(2+cos(v))*sin(u)',
    z: 'sin(v)',
    parameters: ['u', 'v'],
    degree: 4,
    box: [-4, -4, -4, 4, 4, 4],
    implicit: 'x^4+2*x^2*y^2+y^4+2*x^2*z^2+2*y^2*z^2+z^4-10*x^2-10*y^2+6*z^2+9',
    group: 'page',
  },
  {
    name: 'hyperboloid_cosh',
    label: 'Hyperboloid of one sheet in cosh/sinh',
    x: 'cosh(u)*cos(v)',
    y: 'cosh(u)*sin(v)',
    z: 'sinh(u)',
    parameters: ['u', 'v'],
    degree: 2,
    domain: ['-1', '1', '-5/2', '5/2'],
    box: [-2, -2, -2, 2, 2, 2],
    implicit: 'x^2+y^2-z^2-1',
    group: 'page',
  },
];

// The menu's names of the public surfaces; a surface not listed gets its name with
// spaces ("new_surface" -> "New surface").
const LABELS = {
  plane: 'Plane',
  elliptic_paraboloid: 'Elliptic paraboloid',
  hyperbolic_paraboloid: 'Hyperbolic paraboloid',
  unit_sphere: 'Unit sphere',
  whitney_umbrella: "Whitney's umbrella",
  cylinder_rational: 'Cylinder (rational)',
  cone_rational: 'Cone (rational)',
  torus_R2_r1: 'Torus, R = 2, r = 1',
  steiner_roman: "Steiner's Roman surface",
  enneper: "Enneper's surface",
  bicubic_graph: 'Bicubic graph',
  biquadratic_patch: 'Biquadratic patch',
};
function labelOf(name) {
  if (LABELS[name]) return LABELS[name];
  const words = name.split('_');
  return [words[0].charAt(0).toUpperCase() + words[0].slice(1), ...words.slice(1)].join(' ');
}

/// The text examples.json must hold for the shared/ folder at `sharedDir`.
export function buildExamples(sharedDir = defaultSharedDir) {
  const bench = path.join(sharedDir, 'bench');
  const surfaces = JSON.parse(fs.readFileSync(path.join(bench, 'surfaces_public.json'), 'utf8'));
  const examples = surfaces.map((s) => {
    const expected = path.join(bench, 'expected', `${s.name}.txt`);
    const example = { name: s.name, label: labelOf(s.name), x: s.x, y: s.y, z: s.z, degree: s.degree, box: boxOf(s.name) };
    if (DOMAINS[s.name]) example.domain = DOMAINS[s.name];
    if (fs.existsSync(expected)) example.implicit = fs.readFileSync(expected, 'utf8').trim();
    return example;
  });
  examples.push(...EXTRA_EXAMPLES);
  const document = {
    source: 'shared/bench/surfaces_public.json and shared/bench/expected/*.txt, then the page\'s own examples; regenerate with node scripts/make-web-examples.mjs',
    examples,
  };
  // One example per line: readable diffs when shared/ changes.
  const lines = examples.map((e) => '    ' + JSON.stringify(e));
  return `{\n  "source": ${JSON.stringify(document.source)},\n  "examples": [\n${lines.join(',\n')}\n  ]\n}\n`;
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  const check = process.argv.includes('--check');
  const text = buildExamples();
  const current = fs.existsSync(examplesPath) ? fs.readFileSync(examplesPath, 'utf8') : '';
  if (check) {
    if (current !== text) {
      console.error(`${path.relative(root, examplesPath)} is out of date: run node scripts/make-web-examples.mjs`);
      process.exit(1);
    }
    console.log(`${path.relative(root, examplesPath)} is up to date`);
  } else if (current === text) {
    console.log(`unchanged ${path.relative(root, examplesPath)}`);
  } else {
    fs.writeFileSync(examplesPath, text);
    console.log(`wrote ${path.relative(root, examplesPath)}`);
  }
}
