// The examples menu: the public benchmark surfaces (examples.json, generated from
// shared/bench by scripts/make-web-examples.mjs), each with its parametrization, the
// implicit equation Singular finds for it, its degree and the box that frames it.

/// Loads examples.json: [{name, label, x, y, z, degree, box, implicit?}].
export async function loadExamples() {
  const response = await fetch(new URL('examples.json', import.meta.url), { cache: 'no-cache' });
  if (!response.ok) throw new Error(`examples.json: ${response.status}`);
  const data = await response.json();
  return Array.isArray(data.examples) ? data.examples : [];
}

/// Fills `select` with one option per example (value = its name), after the first
/// ("choose…") option, which stays.
export function fillExamplesMenu(select, examples) {
  const group = document.createElement('optgroup');
  group.label = 'Benchmark surfaces (shared/bench)';
  for (const e of examples) {
    const option = document.createElement('option');
    option.value = e.name;
    option.textContent = `${e.label} — degree ${e.degree}`;
    group.append(option);
  }
  select.append(group);
}
