// The record a probe writes and its judge reads back: what the graded part's functions gave the
// test. A part's test program is built twice. Its probe links the student's part and runs the
// test; every call the test (or the given code it calls) makes into the part is written down with
// what the call gave back: its value, what it wrote through its arguments, the test's counters it
// moved, and the calls it made back into the test (callbacks), with their answers. Its judge
// links no student code: the part's functions are replaced by ones that read the record, so the
// test runs again in a process of the grader's, computes its own expected values and decides.
// A record is the student's claim and nothing more: it is parsed under a size limit, checked
// event by event against the calls the judge's test makes, and a mismatch fails the test.
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace pt::judge {

/// The graded functions, one number each: a record names the function of every call.
enum class Fn : uint16_t {
  generate_camera_ray = 101,
  camera_ray_through_pixel,
  estimate_pixel,
  intersect_triangle,
  interpolate_normal,
  intersect_sphere,
  intersect_box = 201,
  midpoint_split,
  best_sah_split,
  bvh_traverse_nearest,
  bvh_occluded,
  diffuse_f = 301,
  diffuse_sample_f,
  diffuse_pdf,
  zero_bounce_radiance,
  estimate_direct_hemisphere,
  estimate_direct_importance,
  one_bounce_radiance,
  direct_radiance = 401,
  at_least_one_bounce_radiance,
  estimate_global_illumination,
  power_heuristic,
  estimate_direct_mis,
  pixel_converged = 501,
  sample_pixel_adaptive,
};

/// The callback a BVH walk (Bvh::traverse_nearest, Bvh::occluded) makes for each leaf test: the
/// judge runs the test itself, so its answers and the work it counts are the judge's own.
inline constexpr int kLeafTest = 1;

/// The callbacks an estimator makes through its context's ray query (LightingContext::query):
/// the probe hands the student's code a query that records each ray (grader/judge/
/// recorded_query.h), the judge traces the same ray with its own query, so the rays a rule
/// counts are the judge's count, and the record's answer must be the judge's.
inline constexpr int kQueryIntersect = 2, kQueryOccluded = 3;

/// The name a student knows a function by, for messages.
const char* name_of(Fn fn);

/// A record that does not match the judge's test: a call it does not make, a short or
/// oversized field, an exception the student's function threw, a probe that stopped.
struct RecordError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Bytes of a record under construction, in the machine's own layout (the probe and the judge
/// are built by one compiler from one source).
class Bytes {
 public:
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>, "a record holds plain values only");
    const char* p = reinterpret_cast<const char*>(&v);
    data_.append(p, sizeof(T));
  }
  const std::string& data() const { return data_; }

 private:
  std::string data_;
};

/// Reads a record's fields in order; any read past the end is a RecordError.
class Cursor {
 public:
  Cursor() = default;
  Cursor(const char* begin, const char* end) : p_(begin), end_(end) {}
  template <class T>
  T get() {
    static_assert(std::is_trivially_copyable_v<T>, "a record holds plain values only");
    if (size_t(end_ - p_) < sizeof(T)) throw RecordError("the record ends inside a value");
    T v;
    std::memcpy(&v, p_, sizeof(T));
    p_ += sizeof(T);
    return v;
  }
  bool done() const { return p_ == end_; }

 private:
  const char* p_ = nullptr;
  const char* end_ = nullptr;
};

// ---- The probe's side -------------------------------------------------------------------------

/// Starts recording to descriptor `fd` (the probe's main, from PT_RECORD_FD).
void start_recording(int fd);
/// Writes out what is buffered (at the end of the program, and before an abnormal end).
void flush_record();
bool recording();

/// One call into the graded part, as the probe sees it. Only calls from outside the part are
/// recorded (the test's, the given code's); a call the student's code makes to its own functions
/// is part of the outer call's work.
class ProbeCall {
 public:
  explicit ProbeCall(Fn fn);
  ~ProbeCall();
  ProbeCall(const ProbeCall&) = delete;
  ProbeCall& operator=(const ProbeCall&) = delete;
  /// The outputs, in the order the judge reads them; write them after the call returns.
  Bytes out;
  /// The call returned: writes its outputs and counter moves.
  void returned();
  /// A call the test made (recorded), not one the student's code made to its own functions.
  bool top() const { return top_; }

 private:
  Fn fn_;
  bool top_ = false;
  bool finished_ = false;
};

/// A call the student's code makes back into the test (a std::function it was handed): its
/// arguments are written before it runs, its answer after. Calls into the graded part made from
/// inside it are recorded as the test's own.
class ProbeCallback {
 public:
  /// `any_depth`: recorded wherever the graded call's own code makes it (a ray traced from a
  /// function the call's code calls), not only from the call itself.
  ProbeCallback(Fn fn, int which, bool any_depth = false);
  ~ProbeCallback();
  ProbeCallback(const ProbeCallback&) = delete;
  ProbeCallback& operator=(const ProbeCallback&) = delete;
  Bytes args;  ///< fill before begin()
  Bytes answer;  ///< fill before end()
  void begin();
  void end();

 private:
  Fn fn_;
  int which_;
  bool live_ = false;
  int saved_depth_ = 0;
  std::vector<int64_t> at_begin_;
};

// ---- The judge's side -------------------------------------------------------------------------

/// Loads a record (the judge's main, from PT_REPLAY_FILE).
void load_record(std::string bytes);
/// Whether every event of the record was read (a record longer than the test's calls fails).
bool record_consumed();

/// One call into the graded part, as the judge replays it: the record must hold a call of `fn`
/// next. Callbacks the student's code made are replayed by `callback` (which reads the
/// arguments, calls the judge's own std::function and checks its answer against the record's)
/// until the call's outputs, which `result()` hands back.
class JudgeCall {
 public:
  explicit JudgeCall(Fn fn);
  /// Replays every callback up to the call's end; then the outputs.
  template <class OnCallback>
  Cursor& finish(OnCallback&& callback) {
    for (;;) {
      int which = 0;
      Cursor args;
      if (!next_callback(&which, &args)) break;
      Cursor answer = callback(which, args);
      (void)answer;
    }
    return out_;
  }
  Cursor& finish() {
    return finish([this](int, Cursor&) -> Cursor {
      throw RecordError(std::string("the record holds a callback from ") + name_of(fn_) +
                        ", which takes none");
    });
  }
  /// The answer the probe's callback gave, read after the judge's own callback has run.
  Cursor callback_answer();

 private:
  bool next_callback(int* which, Cursor* args);
  Fn fn_;
  Cursor out_;
};

/// The record's answer to a callback must equal what the judge's callback answered.
template <class T>
void expect_same_answer(Fn fn, Cursor& recorded, const T& judge_answer) {
  T r = recorded.get<T>();
  if (std::memcmp(&r, &judge_answer, sizeof(T)) != 0)
    throw RecordError(std::string("the record of ") + name_of(fn) +
                      " says a callback answered what the test's callback does not answer");
}

}  // namespace pt::judge
