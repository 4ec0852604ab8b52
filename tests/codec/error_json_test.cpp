// Tests of server/codec/src/error_json.cpp and server_json.cpp: the error bodies and
// the server's own lines.
#include "implicitizer/codec/error_json.hpp"

#include <gtest/gtest.h>

#include <string>

#include "implicitizer/codec/server_json.hpp"
#include "implicitizer/core/errors.hpp"

namespace implicitizer {
namespace {

TEST(EncodeError, Shapes) {
  EXPECT_EQ(encode_error(InputError("unexpected_character", "bad \"$\"", 3).in_field("y")),
            R"({"error":{"code":"unexpected_character","message":"bad \"$\"","position":3,"field":"y"}})");
  EXPECT_EQ(encode_error(InputError("missing_field", "no")), R"({"error":{"code":"missing_field","message":"no"}})");
  EXPECT_EQ(encode_error(NoSingleEquation("curve", {"x^2-y", "y^2-x*z"})),
            R"({"error":{"code":"no_single_equation","message":"curve","generators":["x^2-y","y^2-x*z"]}})");
  EXPECT_EQ(encode_error(LimitExceeded(Limit::time, "slow")),
            R"({"error":{"code":"time_limit_exceeded","message":"slow","limit":"time"}})");
  EXPECT_EQ(encode_error(ToleranceNotMet("too tight", 2.5e-5)),
            R"({"error":{"code":"tolerance_not_met","message":"too tight","best_bound":0.000025}})");
  EXPECT_EQ(encode_error("not_found", "no such path"), R"({"error":{"code":"not_found","message":"no such path"}})");
}

TEST(EncodeServerLines, HealthAndAccessLog) {
  EXPECT_EQ(encode_health_status("ok"), R"({"status":"ok"})");
  EXPECT_EQ(encode_access_log_entry("POST", "/v1/implicitize", 200, 3.25, 924),
            R"({"method":"POST","path":"/v1/implicitize","status":200,"ms":3.25,"bytes":924})");
  EXPECT_EQ(encode_access_log_entry("GET", "/a\"b", 404, 0, 0),
            R"({"method":"GET","path":"/a\"b","status":404,"ms":0.0,"bytes":0})");
}

}  // namespace
}  // namespace implicitizer
