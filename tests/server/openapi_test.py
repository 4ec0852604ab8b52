#!/usr/bin/env python3
"""docs/openapi.yaml against the code (ctest server.openapi).

    openapi_test.py OPENAPI_PROBE docs/openapi.yaml docs/api.md

Checks, with the router and the codec as the truth (tests/server/openapi_probe.cpp):
- the YAML is OpenAPI 3.0 and every local $ref resolves;
- its paths are exactly Router::routes() plus the one static-file path, and each
  path's operations are exactly the route's Allow header (lower-cased);
- each request schema's properties are exactly the fields the decoder accepts (read
  from its `unknown_field` message), its `required` list is what the decoder
  requires, and its example decodes;
- every status of docs/api.md's error table is a response somewhere in the YAML,
  and docs/api.md links the YAML.
Needs Python 3 and python3-yaml (Debian), nothing else.
"""

import json
import re
import subprocess
import sys

import yaml

HTTP_METHODS = {"get", "put", "post", "delete", "options", "head", "patch", "trace"}
REQUESTS = {"/v1/implicitize": ("implicitize", "ImplicitizeRequest"),
            "/v1/groebner": ("groebner", "GroebnerRequest"),
            "/v1/resultant": ("resultant", "ResultantRequest"),
            "/v1/sdf": ("sdf", "SdfRequest"),
            "/v1/render": ("render", "RenderRequest")}

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def walk(node, path=""):
    if isinstance(node, dict):
        for key, value in node.items():
            yield from walk(value, f"{path}/{key}")
        if "$ref" in node:
            yield path, node["$ref"]
    elif isinstance(node, list):
        for i, value in enumerate(node):
            yield from walk(value, f"{path}/{i}")


def resolve(spec, ref):
    if not ref.startswith("#/"):
        return None
    node = spec
    for part in ref[2:].split("/"):
        if not isinstance(node, dict) or part not in node:
            return None
        node = node[part]
    return node


def decode(probe, endpoint, body):
    out = subprocess.run([probe, "decode", endpoint], input=json.dumps(body).encode(), capture_output=True,
                         check=True, timeout=30).stdout.decode()
    if out.strip() == "ok":
        return None
    code, field, message = out[len("error "):].rstrip("\n").split("\t", 2)
    return code, field, message


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    probe, spec_path, api_md_path = sys.argv[1:]
    with open(spec_path, encoding="utf-8") as f:
        spec = yaml.safe_load(f)
    with open(api_md_path, encoding="utf-8") as f:
        api_md = f.read()

    check(str(spec.get("openapi", "")).startswith("3.0."), "openapi: must be a 3.0.x version")
    for where, ref in walk(spec):
        check(resolve(spec, ref) is not None, f"{where}: $ref {ref} does not resolve")

    routes = {}
    lines = subprocess.run([probe, "routes"], capture_output=True, check=True, timeout=30).stdout.decode()
    for line in lines.splitlines():
        path, allow = line.split("\t")
        routes[path] = {m.strip().lower() for m in allow.split(",")}
    check(len(routes) >= 4, f"the router lists only {sorted(routes)}")

    paths = spec.get("paths", {})
    static = [p for p, item in paths.items() if item.get("x-implicitizer-static")]
    check(len(static) == 1, f"expected one path marked x-implicitizer-static, found {static}")
    for path, methods in routes.items():
        if path not in paths:
            check(False, f"route {path} ({', '.join(sorted(methods))}) is missing from {spec_path}")
            continue
        documented = set(paths[path]) & HTTP_METHODS
        check(documented == methods,
              f"{path}: the YAML documents {sorted(documented)}, the router allows {sorted(methods)}")
    for path, item in paths.items():
        if item.get("x-implicitizer-static"):
            documented = set(item) & HTTP_METHODS
            check(documented == {"get", "head", "options"}, f"{path}: static files are GET, HEAD, OPTIONS")
        else:
            check(path in routes, f"{spec_path} documents {path}, which the router does not know")

    schemas = spec.get("components", {}).get("schemas", {})
    for path, (endpoint, schema_name) in REQUESTS.items():
        if path not in routes:
            continue
        schema = schemas.get(schema_name, {})
        ref = paths.get(path, {}).get("post", {}).get("requestBody", {}).get("content", {}) \
            .get("application/json", {}).get("schema", {}).get("$ref")
        check(ref == f"#/components/schemas/{schema_name}", f"{path}: request body must be {schema_name}")
        properties = set(schema.get("properties", {}))
        example = schema.get("example")
        # Mutually exclusive fields (x-implicitizer-one-of, e.g. /v1/sdf's implicit or
        # scene): the example sets one, x-implicitizer-alternative-examples the others.
        one_of = set(schema.get("x-implicitizer-one-of", []))
        alternatives = list(schema.get("x-implicitizer-alternative-examples", []))
        examples = [example] + alternatives
        covered = set().union(*(set(e) for e in examples if isinstance(e, dict)))
        check(all(isinstance(e, dict) for e in examples) and covered == properties,
              f"{schema_name}: the examples must set every property")
        if not isinstance(example, dict):
            continue
        for e in examples:
            check(not one_of or len(one_of & set(e)) == 1,
                  f"{schema_name}: an example must set exactly one of {sorted(one_of)}")
            result = decode(probe, endpoint, e)
            check(result is None, f"{schema_name}: the codec refuses the example {e}: {result}")
        if one_of and len(one_of & set(example)) == 1:
            both = dict(example)
            for alternative in alternatives:
                if isinstance(alternative, dict):
                    both.update({f: alternative[f] for f in one_of if f in alternative})
            check(len(one_of & set(both)) < 2 or decode(probe, endpoint, both) is not None,
                  f"{schema_name}: {sorted(one_of)} together must be refused")
        # Fields the codec accepts: the unknown_field error lists them.
        result = decode(probe, endpoint, dict(example, openapi_test_unknown=1))
        match = result and result[0] == "unknown_field" and re.search(r"\(allowed: ([^)]*)\)", result[2])
        check(bool(match), f"{schema_name}: an unknown field was not refused with its list: {result}")
        if match:
            accepted = {name.strip() for name in match.group(1).split(",")}
            check(accepted == properties, f"{schema_name}: the YAML lists {sorted(properties)}, "
                                          f"the codec accepts {sorted(accepted)}")
        required = set()
        for field in sorted(properties - one_of):
            result = decode(probe, endpoint, {k: v for k, v in example.items() if k != field})
            if result is not None and result[0] == "missing_field" and result[1] == field:
                required.add(field)
        if one_of:
            result = decode(probe, endpoint, {k: v for k, v in example.items() if k not in one_of})
            check(result is not None and result[0] == "missing_field",
                  f"{schema_name}: without any of {sorted(one_of)} the codec must answer missing_field: {result}")
        check(required == set(schema.get("required", [])),
              f"{schema_name}: required is {sorted(schema.get('required', []))}, the codec requires {sorted(required)}")

    statuses = set()

    def collect(node):
        if isinstance(node, dict):
            for key, value in node.items():
                if key == "responses" and isinstance(value, dict):
                    statuses.update(str(k) for k in value)
                collect(value)
        elif isinstance(node, list):
            for value in node:
                collect(value)
    collect(spec)
    table = api_md.split("## Errors", 1)[-1].split("\n## ", 1)[0]
    for status in sorted(set(re.findall(r"^\| (\d{3}) \|", table, re.M))):
        check(status in statuses, f"docs/api.md lists status {status}, the YAML has no such response")
    check("openapi.yaml" in api_md, "docs/api.md must link openapi.yaml")

    for failure in failures:
        print("FAIL:", failure)
    print(f"openapi_test: {len(routes)} routes, {len(paths)} documented paths, {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
