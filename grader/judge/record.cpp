#include "grader/judge/record.h"

#include <unistd.h>

#include <algorithm>

#include "framework/testing/observed_counters.h"

namespace pt::judge {
namespace {

enum Kind : uint8_t { kCall = 'C', kReturn = 'R', kThrew = 'X', kCallback = 'B', kAnswer = 'A' };

#pragma pack(push, 1)
struct Header {
  uint8_t kind;
  uint16_t fn;
  uint8_t which;
  uint32_t size;
};
#pragma pack(pop)

// The largest single event a judge accepts: no graded function gives back more than a few
// hundred bytes, so anything larger is not a record of one.
constexpr uint32_t kMaxEvent = 1u << 16;

using Counter = test::ObservedCounter;
const std::vector<Counter>& counters() { return test::observed_counters(); }

std::vector<int64_t> snapshot() {
  std::vector<int64_t> v;
  for (const Counter& c : counters())
    v.push_back(c.wide ? int64_t(*static_cast<uint64_t*>(c.at)) : int64_t(*static_cast<long*>(c.at)));
  return v;
}

// ---- probe state
int record_fd = -1;
std::string buffer;
int depth = 0;
struct Frame {
  std::vector<int64_t> at_start;
  std::vector<int64_t> excluded;  // what callbacks moved: the test's own doing, done again in the judge
};
std::vector<Frame> frames;

void write_event(Kind kind, Fn fn, int which, const std::string& payload) {
  Header h{kind, uint16_t(fn), uint8_t(which), uint32_t(payload.size())};
  buffer.append(reinterpret_cast<const char*>(&h), sizeof h);
  buffer.append(payload);
  if (buffer.size() > (1u << 20)) flush_record();
}

// ---- judge state
std::string record;
size_t at = 0;

bool peek(Header* h) {
  if (record.size() - at < sizeof(Header)) return false;
  std::memcpy(h, record.data() + at, sizeof(Header));
  return true;
}

Cursor take(const Header& h) {
  if (h.size > kMaxEvent || record.size() - at - sizeof(Header) < h.size)
    throw RecordError("the record is cut short or malformed");
  const char* begin = record.data() + at + sizeof(Header);
  at += sizeof(Header) + h.size;
  return Cursor(begin, begin + h.size);
}

std::string what_is(const Header& h) {
  switch (h.kind) {
    case kCall: return std::string("a call of ") + name_of(Fn(h.fn));
    case kReturn: return std::string("the end of a call of ") + name_of(Fn(h.fn));
    case kThrew: return std::string("an exception from ") + name_of(Fn(h.fn));
    case kCallback: return std::string("a callback from ") + name_of(Fn(h.fn));
    case kAnswer: return std::string("a callback's answer to ") + name_of(Fn(h.fn));
  }
  return "bytes that are no event";
}

}  // namespace

const char* name_of(Fn fn) {
  switch (fn) {
    case Fn::generate_camera_ray: return "generate_camera_ray";
    case Fn::camera_ray_through_pixel: return "camera_ray_through_pixel";
    case Fn::estimate_pixel: return "estimate_pixel";
    case Fn::intersect_triangle: return "intersect_triangle";
    case Fn::interpolate_normal: return "interpolate_normal";
    case Fn::intersect_sphere: return "intersect_sphere";
    case Fn::intersect_box: return "intersect_box";
    case Fn::midpoint_split: return "midpoint_split";
    case Fn::best_sah_split: return "best_sah_split";
    case Fn::bvh_traverse_nearest: return "Bvh::traverse_nearest";
    case Fn::bvh_occluded: return "Bvh::occluded";
    case Fn::diffuse_f: return "DiffuseBsdf::f";
    case Fn::diffuse_sample_f: return "DiffuseBsdf::sample_f";
    case Fn::diffuse_pdf: return "DiffuseBsdf::pdf";
    case Fn::zero_bounce_radiance: return "zero_bounce_radiance";
    case Fn::estimate_direct_hemisphere: return "estimate_direct_hemisphere";
    case Fn::estimate_direct_importance: return "estimate_direct_importance";
    case Fn::one_bounce_radiance: return "one_bounce_radiance";
    case Fn::direct_radiance: return "direct_radiance";
    case Fn::at_least_one_bounce_radiance: return "at_least_one_bounce_radiance";
    case Fn::estimate_global_illumination: return "estimate_global_illumination";
    case Fn::power_heuristic: return "power_heuristic";
    case Fn::estimate_direct_mis: return "estimate_direct_mis";
    case Fn::pixel_converged: return "pixel_converged";
    case Fn::sample_pixel_adaptive: return "sample_pixel_adaptive";
  }
  return "an unknown function";
}

// ---- probe

void start_recording(int fd) { record_fd = fd; }
bool recording() { return record_fd >= 0; }

void flush_record() {
  const char* p = buffer.data();
  size_t left = buffer.size();
  while (left > 0 && record_fd >= 0) {
    ssize_t n = write(record_fd, p, left);
    if (n <= 0) break;  // the grader's limit: the judge sees a record cut short
    p += n;
    left -= size_t(n);
  }
  buffer.clear();
}

ProbeCall::ProbeCall(Fn fn) : fn_(fn) {
  top_ = depth == 0 && recording();
  ++depth;
  if (!top_) return;
  write_event(kCall, fn, 0, "");
  frames.push_back({snapshot(), {}});
  frames.back().excluded.assign(frames.back().at_start.size(), 0);
}

void ProbeCall::returned() {
  if (!top_ || finished_) return;
  finished_ = true;
  Frame f = frames.back();
  frames.pop_back();
  std::vector<int64_t> now = snapshot();
  Bytes payload;
  payload.put(uint32_t(now.size()));
  for (size_t i = 0; i < now.size(); ++i) {
    int64_t before = i < f.at_start.size() ? f.at_start[i] : 0;
    int64_t skip = i < f.excluded.size() ? f.excluded[i] : 0;
    payload.put(int64_t(now[i] - before - skip));
  }
  write_event(kReturn, fn_, 0, payload.data() + out.data());
}

ProbeCall::~ProbeCall() {
  --depth;
  if (top_ && !finished_) {
    // Left by an exception: the judge's replay throws too, and the test fails as it did here.
    if (!frames.empty()) frames.pop_back();
    write_event(kThrew, fn_, 0, "");
  }
}

ProbeCallback::ProbeCallback(Fn fn, int which, bool any_depth) : fn_(fn), which_(which) {
  // Only a callback handed to a call the test made is the test's: one the student's own code
  // passes between its functions is part of the outer call's work.
  live_ = recording() && (depth == 1 || (any_depth && depth > 1)) && !frames.empty();
}

void ProbeCallback::begin() {
  if (!live_) return;
  write_event(kCallback, fn_, which_, args.data());
  at_begin_ = snapshot();
  saved_depth_ = depth;
  depth = 0;
}

void ProbeCallback::end() {
  if (!live_) return;
  depth = saved_depth_;
  std::vector<int64_t> now = snapshot();
  Frame& f = frames.back();
  for (size_t i = 0; i < std::min({now.size(), at_begin_.size(), f.excluded.size()}); ++i)
    f.excluded[i] += now[i] - at_begin_[i];
  write_event(kAnswer, fn_, which_, answer.data());
}

ProbeCallback::~ProbeCallback() {
  if (live_ && depth == 0) depth = saved_depth_;  // the callback threw: the call's frame goes on
}

// ---- judge

void load_record(std::string bytes) {
  record = std::move(bytes);
  at = 0;
}
bool record_consumed() { return at == record.size(); }

JudgeCall::JudgeCall(Fn fn) : fn_(fn) {
  Header h;
  if (!peek(&h))
    throw RecordError(std::string("your code stopped before it returned from a call of ") +
                      name_of(fn) + " (it crashed, ran out of time, or exited)");
  if (h.kind != kCall || Fn(h.fn) != fn)
    throw RecordError(std::string("the test calls ") + name_of(fn) + " here, but the record holds " +
                      what_is(h) + ": the probe did not run this test as written");
  take(h);
}

bool JudgeCall::next_callback(int* which, Cursor* args) {
  Header h;
  if (!peek(&h))
    throw RecordError(std::string("your ") + name_of(fn_) +
                      " did not return (it crashed, ran out of time, or exited)");
  if (Fn(h.fn) != fn_)
    throw RecordError(std::string("inside ") + name_of(fn_) + " the record holds " + what_is(h));
  if (h.kind == kThrew) {
    take(h);
    throw RecordError(std::string("your ") + name_of(fn_) + " threw an exception");
  }
  if (h.kind == kCallback) {
    *which = h.which;
    *args = take(h);
    return true;
  }
  if (h.kind != kReturn)
    throw RecordError(std::string("inside ") + name_of(fn_) + " the record holds " + what_is(h));
  out_ = take(h);
  uint32_t n = out_.get<uint32_t>();
  if (n != counters().size())
    throw RecordError(std::string("the record of ") + name_of(fn_) +
                      " moves a number of counters the test does not have");
  // Every counter a test reads moves only in its callbacks (a leaf test, a ray of the context's
  // query, a callback of the test's), which the judge has just made again itself: what the
  // record says the call moved outside them is the student's code writing the test's counters.
  for (size_t i = 0; i < counters().size(); ++i) {
    if (out_.get<int64_t>() != 0)
      throw RecordError(std::string("your ") + name_of(fn_) +
                        " changed a counter of the test's itself (the judge counts the work a "
                        "call does: the rays it traces, the leaves it tests)");
  }
  return false;
}

Cursor JudgeCall::callback_answer() {
  Header h;
  if (!peek(&h) || h.kind != kAnswer || Fn(h.fn) != fn_)
    throw RecordError(std::string("a callback from ") + name_of(fn_) + " has no answer in the record");
  return take(h);
}

}  // namespace pt::judge
