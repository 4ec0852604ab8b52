-- wrk script: POST /v1/implicitize with the same body every time, so after the first
-- answer every request is a cache hit (unless the server runs with --cache-size 0).
--   wrk -s implicitize.lua URL/v1/implicitize -- sphere|biquadratic
-- sphere: the rational unit sphere (about 0.2 ms of algebra);
-- biquadratic: biquadratic_patch of the public suite (degree 8, 10-30 ms), the
-- slow surface of the overload run.

local dir = debug.getinfo(1, "S").source:match("^@(.*/)") or "./"
dofile(dir .. "status_counts.lua")

local bodies = {
  sphere = '{"x":"2*s/(s^2+t^2+1)","y":"2*t/(s^2+t^2+1)","z":"(s^2+t^2-1)/(s^2+t^2+1)"}',
  biquadratic = '{"x":"s^2+2*s*t-t+1","y":"s*t^2-s+3*t","z":"s^2*t^2+s-2*t^2"}',
}

wrk.method = "POST"
wrk.headers["Content-Type"] = "application/json"

-- wrk formats the (static) request after init returns, with this body.
function init(args)
  local name = args[1] or "sphere"
  wrk.body = bodies[name] or error("implicitize.lua: unknown surface " .. name)
end
