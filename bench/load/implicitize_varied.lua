-- wrk script: POST /v1/implicitize of the unit sphere with a different body on every
-- request, so that every request misses the server's cache and is computed.
--   wrk -s implicitize_varied.lua URL/v1/implicitize
-- Request n of thread i multiplies numerator and denominator of each coordinate by
-- k = i*10^8 + n + 1 (never 1, unique across threads): the same parametrization
-- of the same sphere, but a different text, and the cache is keyed on the text of
-- x, y and z. The answer stays x^2+y^2+z^2-1; the cost is that of the plain sphere
-- up to the cancellation of k.

local dir = debug.getinfo(1, "S").source:match("^@(.*/)") or "./"
dofile(dir .. "status_counts.lua")

wrk.method = "POST"
wrk.headers["Content-Type"] = "application/json"

local sent = 0

-- Defining `request` makes wrk call it for every request (a "dynamic" script).
function request()
  sent = sent + 1
  local k = string.format("%d", thread_index * 100000000 + sent + 1)
  local body = string.format(
    '{"x":"2*%s*s/(%s*(s^2+t^2+1))","y":"2*%s*t/(%s*(s^2+t^2+1))","z":"%s*(s^2+t^2-1)/(%s*(s^2+t^2+1))"}',
    k, k, k, k, k, k)
  return wrk.format(nil, nil, nil, body)
end
