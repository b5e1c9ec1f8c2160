#include "fake_pupil.hpp"

#include <chrono>
#include <cstdio>
#include <msgpack.hpp>

namespace foveate::gaze::testing {

namespace {

int port_of(zmq::socket_t& s) {
  const std::string ep = s.get(zmq::sockopt::last_endpoint);
  return std::stoi(ep.substr(ep.rfind(':') + 1));
}

double steady_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

FakePupil::FakePupil(double clock_offset_s, int control_port) : control_port_(control_port) {
  start(clock_offset_s);
}

FakePupil::~FakePupil() { stop(); }

double FakePupil::clock() const { return steady_s() + offset_.load(); }

void FakePupil::start(double clock_offset_s) {
  offset_.store(clock_offset_s);
  rep_ = std::make_unique<zmq::socket_t>(ctx_, zmq::socket_type::rep);
  rep_->set(zmq::sockopt::linger, 0);
  rep_->set(zmq::sockopt::rcvtimeo, 20);
  // The control port survives restarts; retry briefly if the old listener lingers.
  const std::string ep = "tcp://127.0.0.1:" + (control_port_ ? std::to_string(control_port_) : "*");
  for (int i = 0;; ++i) {
    try {
      rep_->bind(ep);
      break;
    } catch (const zmq::error_t&) {
      if (i == 100) throw;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
  }
  control_port_ = port_of(*rep_);
  pub_ = std::make_unique<zmq::socket_t>(ctx_, zmq::socket_type::pub);
  pub_->set(zmq::sockopt::linger, 0);
  pub_->bind("tcp://127.0.0.1:*");
  pub_port_ = port_of(*pub_);
  stop_.store(false);
  thread_ = std::thread([this] { serve(); });
}

void FakePupil::stop() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
  rep_.reset();
  pub_.reset();
}

void FakePupil::serve() {
  while (!stop_.load()) {
    zmq::message_t req;
    if (!rep_->recv(req, zmq::recv_flags::none)) continue;
    ++requests;
    const std::string what = req.to_string();
    std::string reply = "unknown command";
    if (what == "SUB_PORT") {
      std::lock_guard<std::mutex> lock(answer_mu_);
      reply = sub_port_answer_.empty() ? std::to_string(pub_port_) : sub_port_answer_;
    } else if (what == "t") {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.6f", clock());
      reply = buf;
    }
    rep_->send(zmq::buffer(reply), zmq::send_flags::none);
  }
}

void FakePupil::publish(const std::vector<std::string>& parts) {
  for (size_t i = 0; i < parts.size(); ++i) {
    pub_->send(zmq::buffer(parts[i]),
               i + 1 < parts.size() ? zmq::send_flags::sndmore : zmq::send_flags::none);
  }
}

std::string FakePupil::pack_gaze(double x, double y, double confidence, double timestamp) {
  msgpack::sbuffer buf;
  msgpack::packer<msgpack::sbuffer> pk(&buf);
  pk.pack_map(5);
  pk.pack(std::string("topic"));
  pk.pack(std::string("gaze.2d.0."));
  pk.pack(std::string("norm_pos"));
  pk.pack_array(2);
  pk.pack(x);
  pk.pack(y);
  pk.pack(std::string("confidence"));
  pk.pack(confidence);
  pk.pack(std::string("timestamp"));
  pk.pack(timestamp);
  pk.pack(std::string("base_data"));
  pk.pack_array(0);
  return std::string(buf.data(), buf.size());
}

void FakePupil::publish_gaze(double x, double y, double confidence, double timestamp) {
  publish({"gaze.2d.0.", pack_gaze(x, y, confidence, timestamp)});
}

int unused_port() {
  zmq::context_t ctx(1);
  zmq::socket_t s(ctx, zmq::socket_type::rep);
  s.set(zmq::sockopt::linger, 0);
  s.bind("tcp://127.0.0.1:*");
  return port_of(s);
}

}  // namespace foveate::gaze::testing
