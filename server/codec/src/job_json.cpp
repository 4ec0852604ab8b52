#include "implicitizer/codec/job_json.hpp"

#include "json_reader.hpp"
#include "json_writer.hpp"

namespace implicitizer {

JobSubmission decode_job_submission(std::string_view body, const JsonParams& limits) {
  // The wrapper adds one level to the deepest body an endpoint accepts (a scene's);
  // the endpoint applies its own limit to `request` when it decodes it.
  JsonParams wrapper_limits = json::with_room_for_a_scene(limits);
  wrapper_limits.max_depth += 1;
  const rapidjson::Document document = json::parse_object(body, wrapper_limits);
  json::ObjectReader reader(document);
  JobSubmission submission;
  submission.kind = json::read_string(reader.require("kind"), "kind");
  const rapidjson::Value& request = reader.require("request");
  if (!request.IsObject()) throw json::wrong_type("request", "an object");
  reader.finish("kind, request");
  // parse_object bounded the nesting, so writing it back recurses at most that deep.
  rapidjson::StringBuffer buffer;
  json::Writer w(buffer);
  request.Accept(w);
  submission.request = json::finish(buffer);
  return submission;
}

namespace {

void write_progress(json::Writer& w, const JobProgressView& p) {
  w.StartObject();
  w.Key("phase");
  json::write_string(w, p.phase);
  w.Key("fraction");
  if (p.fraction) {
    w.Double(*p.fraction);
  } else {
    w.Null();
  }
  w.Key("done");
  w.Uint64(p.done);
  w.Key("total");
  w.Uint64(p.total);
  if (!p.stage.empty()) {
    w.Key("stage");
    w.StartObject();
    w.Key("phase");
    json::write_string(w, p.stage);
    w.Key("done");
    w.Uint64(p.stage_done);
    w.Key("total");
    w.Uint64(p.stage_total);
    w.EndObject();
  }
  w.Key("elapsed_ms");
  json::write_milliseconds(w, p.elapsed_ms);
  w.EndObject();
}

}  // namespace

std::string encode_job(const JobView& job) {
  return json::write_json([&](json::Writer& w) {
    w.StartObject();
    w.Key("id");
    json::write_string(w, job.id);
    w.Key("kind");
    json::write_string(w, job.kind);
    w.Key("status");
    json::write_string(w, job.status);
    w.Key("cancel_requested");
    w.Bool(job.cancel_requested);
    w.Key("progress");
    write_progress(w, job.progress);
    if (job.http_status) {
      w.Key("http_status");
      w.Uint(*job.http_status);
    }
    if (job.result_json) {
      w.Key("result");
      // The endpoint's own encoder wrote it: embedded as it is, byte for byte.
      w.RawValue(job.result_json->data(), job.result_json->size(), rapidjson::kObjectType);
    }
    if (!job.result_url.empty()) {
      w.Key("result_url");
      json::write_string(w, job.result_url);
    }
    w.EndObject();
  });
}

}  // namespace implicitizer
