#include "foveate/gaze/pupil.hpp"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <msgpack.hpp>
#include <mutex>
#include <thread>
#include <zmq.hpp>

#include "foveate/core/error.hpp"

namespace foveate::gaze {

// ------------------------------------------------------------ decoding

namespace {

// Pupil's gaze datum is a small map (a few dozen keys, nesting about five deep
// through base_data). These bounds reject anything far larger before msgpack
// allocates for it: a header declaring 2^32 elements is refused, not allocated.
const msgpack::unpack_limit kLimits(/*array*/ 256, /*map*/ 128, /*str*/ 4096, /*bin*/ 4096,
                                    /*ext*/ 0, /*depth*/ 10);
constexpr std::size_t kMaxTopicBytes = 256;
constexpr int kMaxParts = 8;

bool as_number(const msgpack::object& o, double& out) {
  switch (o.type) {
    case msgpack::type::FLOAT32:
    case msgpack::type::FLOAT64:
      out = o.via.f64;
      return true;
    case msgpack::type::POSITIVE_INTEGER:
      out = static_cast<double>(o.via.u64);
      return true;
    case msgpack::type::NEGATIVE_INTEGER:
      out = static_cast<double>(o.via.i64);
      return true;
    default:
      return false;
  }
}

bool key_is(const msgpack::object& k, std::string_view name) {
  if (k.type == msgpack::type::STR) return std::string_view(k.via.str.ptr, k.via.str.size) == name;
  if (k.type == msgpack::type::BIN) return std::string_view(k.via.bin.ptr, k.via.bin.size) == name;
  return false;
}

}  // namespace

std::optional<PupilGaze> decode_pupil_gaze(std::string_view payload) {
  try {
    std::size_t off = 0;
    const msgpack::object_handle oh =
        msgpack::unpack(payload.data(), payload.size(), off, nullptr, nullptr, kLimits);
    if (off != payload.size()) return std::nullopt;  // trailing bytes
    const msgpack::object& root = oh.get();
    if (root.type != msgpack::type::MAP) return std::nullopt;
    bool has_pos = false, has_conf = false, has_ts = false;
    PupilGaze g;
    for (std::uint32_t i = 0; i < root.via.map.size; ++i) {
      const msgpack::object_kv& kv = root.via.map.ptr[i];
      if (key_is(kv.key, "norm_pos")) {
        if (kv.val.type != msgpack::type::ARRAY || kv.val.via.array.size != 2) return std::nullopt;
        double x = 0, y = 0;
        if (!as_number(kv.val.via.array.ptr[0], x) || !as_number(kv.val.via.array.ptr[1], y)) {
          return std::nullopt;
        }
        g.pos = {x, 1.0 - y};  // Pupil: origin bottom-left
        has_pos = true;
      } else if (key_is(kv.key, "confidence")) {
        if (!as_number(kv.val, g.confidence)) return std::nullopt;
        has_conf = true;
      } else if (key_is(kv.key, "timestamp")) {
        if (!as_number(kv.val, g.timestamp)) return std::nullopt;
        has_ts = true;
      }
    }
    if (!has_pos || !has_conf || !has_ts) return std::nullopt;
    return g;
  } catch (const std::exception&) {
    return std::nullopt;  // msgpack: malformed, truncated or over a limit
  }
}

PupilOptions parse_pupil_address(const std::string& address) {
  PupilOptions o;
  if (address.empty()) return o;
  const auto c = address.rfind(':');
  std::string host = address, port;
  if (c != std::string::npos) {
    host = address.substr(0, c);
    port = address.substr(c + 1);
  }
  if (host.empty() || host.find_first_of(" /") != std::string::npos) {
    throw Error(
        "gaze source pupil: expected pupil:HOST:PORT (e.g. pupil:127.0.0.1:50020), got 'pupil:" +
        address + "'");
  }
  o.host = host;
  if (c != std::string::npos) {
    char* end = nullptr;
    const long p = std::strtol(port.c_str(), &end, 10);
    if (port.empty() || *end != '\0' || p < 1 || p > 65535) {
      throw Error("gaze source pupil: the port must be 1..65535, got '" + port + "'");
    }
    o.port = static_cast<int>(p);
  }
  return o;
}

std::string PupilCounters::summary() const {
  return std::to_string(messages) + " gaze messages, " + std::to_string(accepted) + " accepted, " +
         dropped.summary() + ", " + std::to_string(malformed) + " malformed, " +
         std::to_string(connects) + " connects, " + std::to_string(failed_requests) +
         " failed requests" +
         (overflow ? ", " + std::to_string(overflow) + " lost to overflow" : "") +
         (connected ? "; connected" : "; not connected");
}

// ------------------------------------------------------------ the receiver

namespace {
/// An answer quoted in a message: at most 40 bytes, control bytes as '?'.
std::string printable(const std::string& s) {
  std::string out = s.substr(0, 40);
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  }
  return s.size() > 40 ? out + "..." : out;
}
}  // namespace

struct PupilSource::Impl {
  PupilOptions o;
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  zmq::context_t ctx{1};
  std::thread thread;
  std::atomic<bool> stop{false};

  mutable std::mutex mu;
  mutable std::condition_variable cv;
  PupilCounters counters;
  std::deque<GazeSample> queue;
  std::deque<double> arrivals;
  bool have_latest = false;
  GazeSample latest;

  // Receiver-thread state.
  SampleValidator validator;
  std::unique_ptr<zmq::socket_t> sub;
  int sub_port = 0;
  double offset = 0.0;  // tracker clock - local clock
  double last_message = 0.0;

  explicit Impl(PupilOptions opt) : o(std::move(opt)), validator(o.off_screen_limit) {}

  double now() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  std::string endpoint(int port) const { return "tcp://" + o.host + ":" + std::to_string(port); }

  /// One REQ exchange on a fresh socket (a REQ socket whose reply timed out
  /// cannot be reused), bounded by request_timeout_ms both ways.
  std::optional<std::string> request(const std::string& what) {
    try {
      zmq::socket_t req(ctx, zmq::socket_type::req);
      req.set(zmq::sockopt::linger, 0);
      req.set(zmq::sockopt::sndtimeo, o.request_timeout_ms);
      req.set(zmq::sockopt::rcvtimeo, o.request_timeout_ms);
      req.set(zmq::sockopt::maxmsgsize, static_cast<std::int64_t>(4096));
      req.connect(endpoint(o.port));
      if (!req.send(zmq::buffer(what), zmq::send_flags::none)) return std::nullopt;
      zmq::message_t reply;
      if (!req.recv(reply, zmq::recv_flags::none)) return std::nullopt;
      if (reply.more()) return std::nullopt;
      return reply.to_string();
    } catch (const zmq::error_t&) {
      return std::nullopt;
    }
  }

  void fail_request(std::string why) {
    std::lock_guard<std::mutex> lock(mu);
    ++counters.failed_requests;
    counters.connected = false;
    counters.last_failure = std::move(why);
  }

  /// Asks SUB_PORT and t; (re)connects the SUB socket when the port changed.
  bool handshake() {
    const std::optional<std::string> port_text = request("SUB_PORT");
    if (!port_text) return fail_request("no answer to SUB_PORT"), false;
    char* end = nullptr;
    errno = 0;
    const long port = std::strtol(port_text->c_str(), &end, 10);
    if (port_text->empty() || *end != '\0' || errno != 0 || port < 1 || port > 65535) {
      return fail_request("the answer to SUB_PORT, '" + printable(*port_text) +
                          "', is not a valid port (1..65535)"),
             false;
    }
    const double before = now();
    const std::optional<std::string> t_text = request("t");
    const double after = now();
    if (!t_text) return fail_request("no answer to t (the tracker's clock)"), false;
    const double t = std::strtod(t_text->c_str(), &end);
    if (t_text->empty() || *end != '\0' || !std::isfinite(t)) {
      return fail_request("the answer to t, '" + printable(*t_text) +
                          "', is not a time in seconds"),
             false;
    }
    offset = t - 0.5 * (before + after);
    validator.reset_clock();  // a restarted tracker starts a new clock
    // A fresh SUB socket each time: after silence, a dropped connection (an
    // oversized frame makes ZMQ disconnect) or a restart, start clean.
    {
      sub.reset();
      auto s = std::make_unique<zmq::socket_t>(ctx, zmq::socket_type::sub);
      s->set(zmq::sockopt::linger, 0);
      s->set(zmq::sockopt::rcvtimeo, o.receive_timeout_ms);
      s->set(zmq::sockopt::maxmsgsize, o.max_message_bytes);
      s->set(zmq::sockopt::rcvhwm, 1000);
      s->set(zmq::sockopt::reconnect_ivl, 100);
      s->set(zmq::sockopt::subscribe, o.topic);
      s->connect(endpoint(static_cast<int>(port)));
      sub = std::move(s);
      sub_port = static_cast<int>(port);
    }
    last_message = now();
    std::lock_guard<std::mutex> lock(mu);
    ++counters.connects;
    counters.connected = true;
    cv.notify_all();
    return true;
  }

  void malformed() {
    std::lock_guard<std::mutex> lock(mu);
    ++counters.malformed;
  }

  void receive_one() {
    zmq::message_t topic;
    if (!sub->recv(topic, zmq::recv_flags::none)) {
      if (now() - last_message > o.silence_s) {
        std::lock_guard<std::mutex> lock(mu);
        counters.connected = false;
        need_handshake = true;
      }
      return;
    }
    last_message = now();
    // The remaining parts of a multipart message arrive with the first.
    zmq::message_t payload, extra;
    int parts = 1;
    bool more = topic.more();
    while (more && parts < kMaxParts + 1) {
      zmq::message_t& m = parts == 1 ? payload : extra;
      if (!sub->recv(m, zmq::recv_flags::dontwait)) break;
      ++parts;
      more = m.more();
    }
    if (parts != 2 || more || topic.size() > kMaxTopicBytes ||
        topic.to_string_view().substr(0, o.topic.size()) != o.topic) {
      return malformed();
    }
    const std::optional<PupilGaze> g = decode_pupil_gaze(payload.to_string_view());
    if (!g) return malformed();
    const double received = now();
    GazeSample s{g->timestamp - offset, g->pos, g->confidence, true};
    if (std::isfinite(s.time_s) && std::fabs(received - s.time_s) > 2.0 * o.silence_s + 1.0) {
      // The tracker's clock jumped (it restarted on the same port): resync.
      need_handshake = true;
      std::lock_guard<std::mutex> lock(mu);
      ++counters.messages;
      return;
    }
    const bool ok = validator.accept(s);
    std::lock_guard<std::mutex> lock(mu);
    ++counters.messages;
    counters.dropped = validator.counts();
    if (!ok) return;
    ++counters.accepted;
    latest = s;
    have_latest = true;
    if (o.queue_limit > 0) {
      queue.push_back(s);
      arrivals.push_back(received);
      while (queue.size() > o.queue_limit) {
        queue.pop_front();
        arrivals.pop_front();
        ++counters.overflow;
      }
    }
  }

  bool need_handshake = true;

  void run() {
    double backoff = 0.05;
    while (!stop.load()) {
      if (need_handshake) {
        if (!handshake()) {
          // Bounded wait before the next attempt, waking early on stop.
          const double until = now() + backoff;
          while (!stop.load() && now() < until)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
          backoff = std::min(1.0, backoff * 2);
          continue;
        }
        backoff = 0.05;
        need_handshake = false;
      }
      try {
        receive_one();
      } catch (const zmq::error_t&) {
        need_handshake = true;
        sub.reset();
      }
    }
    sub.reset();
  }
};

PupilSource::PupilSource(PupilOptions options) : impl_(std::make_unique<Impl>(std::move(options))) {
  if (impl_->o.request_timeout_ms < 1 || impl_->o.receive_timeout_ms < 1 ||
      !(impl_->o.silence_s > 0) || impl_->o.max_message_bytes < 256) {
    throw Error("pupil: timeouts must be positive and the message limit at least 256 bytes");
  }
  impl_->thread = std::thread([this] { impl_->run(); });
}

PupilSource::~PupilSource() {
  impl_->stop.store(true);
  if (impl_->thread.joinable()) impl_->thread.join();
}

GazeSample PupilSource::sample(double t_s) {
  const double epoch = impl_->now() - t_s;  // render clock -> steady clock
  std::lock_guard<std::mutex> lock(impl_->mu);
  if (!impl_->have_latest) return {t_s, {0.5, 0.5}, 0.0, false};
  GazeSample s = impl_->latest;
  s.time_s -= epoch;
  return s;
}

std::vector<GazeSample> PupilSource::drain(std::vector<double>* arrival_s) {
  std::lock_guard<std::mutex> lock(impl_->mu);
  std::vector<GazeSample> out(impl_->queue.begin(), impl_->queue.end());
  if (arrival_s) arrival_s->assign(impl_->arrivals.begin(), impl_->arrivals.end());
  impl_->queue.clear();
  impl_->arrivals.clear();
  return out;
}

double PupilSource::now_s() const { return impl_->now(); }

PupilCounters PupilSource::counters() const {
  std::lock_guard<std::mutex> lock(impl_->mu);
  return impl_->counters;
}

bool PupilSource::wait_connected(double timeout_s) const {
  std::unique_lock<std::mutex> lock(impl_->mu);
  return impl_->cv.wait_for(lock, std::chrono::duration<double>(timeout_s),
                            [this] { return impl_->counters.connected; });
}

std::string PupilSource::describe() const {
  return "Pupil Capture at " + impl_->o.host + ":" + std::to_string(impl_->o.port);
}

std::string PupilSource::report() const { return "pupil: " + counters().summary(); }

}  // namespace foveate::gaze
