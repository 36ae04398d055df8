#include "lms100_emulator/lms100_emulator.hpp"

#include "common/clock.hpp"
#include "common/cola_a_framing.hpp"
#include "lms100_emulator/emulator_server.hpp"
#include "lms100_emulator/tcp_socket.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <limits>
#include <mutex>
#include <random>
#include <stdexcept>

namespace refloc {

namespace {
constexpr int64_t kMaxWaitUs = 50000;  // re-check the fault knobs at least this often
}  // namespace

void Lms100Emulator::Server::run() {
  pollfd fds[3];
  while (!stop.load()) {
    const int64_t now_mono = monotonic_us();
    apply_faults(now_mono);
    const auto complete_delay = static_cast<uint64_t>(std::llround(
        (device.full_scan_beams() * kTimeIncrementS + config.processing_delay_s + config.link_delay_s) *
        1e6));
    ScanSlot slot;
    // stop is checked per scan: a renderer slower than the scan period (a Debug build) would
    // otherwise always have another scan due and never see it.
    while (!stop.load() && device.scheduler().pop_due_scan(device_now(), complete_delay, slot))
      emit_scan(slot, true);

    int64_t wait_us = kMaxWaitUs;
    const uint64_t now_dev = device_now();
    const uint64_t next = device.scheduler().next_event_us(now_dev, complete_delay);
    if (next != std::numeric_limits<uint64_t>::max()) {
      wait_us = std::min<int64_t>(wait_us, next > now_dev ? static_cast<int64_t>(next - now_dev) : 0);
    }
    if (stalled_until_mono > 0)
      wait_us = std::min(wait_us, std::max<int64_t>(0, stalled_until_mono - monotonic_us()));

    fds[0] = {wake_fd, POLLIN, 0};
    fds[1] = {listen_fd, POLLIN, 0};
    fds[2] = {client_fd, POLLIN, 0};  // poll ignores negative fds
    const timespec timeout{static_cast<time_t>(wait_us / 1000000),
                           static_cast<long>((wait_us % 1000000) * 1000)};
    if (::ppoll(fds, 3, &timeout, nullptr) <= 0) continue;
    if (fds[0].revents & POLLIN) {
      char drain[64];
      while (::read(wake_fd, drain, sizeof(drain)) > 0) {
      }
      apply_faults(monotonic_us());  // before any request is answered under the old settings
    }
    if (fds[1].revents & POLLIN) accept_new_client();
    if (client_fd >= 0 && (fds[2].revents & (POLLIN | POLLHUP | POLLERR))) read_client();
  }
  disconnect();
  close_socket(listen_fd);
}

void Lms100Emulator::Server::apply_faults(int64_t now_mono) {
  settings = faults.settings();
  device.set_refuse_readiness(settings.refuse_readiness);
  if (faults.take_refuse_next_write()) device.arm_refuse_next_write();
  if (faults.take_close_now()) disconnect();
  const int stall_ms = faults.take_stall_ms();
  if (stall_ms > 0) stalled_until_mono = std::max(stalled_until_mono, now_mono + int64_t{stall_ms} * 1000);
  if (stalled_until_mono > 0 && now_mono >= stalled_until_mono) {
    stalled_until_mono = 0;
    if (client_fd >= 0 && !stall_buffer.empty()) {
      std::string burst;
      burst.swap(stall_buffer);
      write_out(burst);
    }
    stall_buffer.clear();
  }
}

void Lms100Emulator::Server::accept_new_client() {
  const int fd = accept_client(listen_fd);
  if (fd < 0) return;
  disconnect();  // the new client replaces the old one
  client_fd = fd;
  configure_client_socket(client_fd, config.send_timeout_ms);
  request_reader.reset();
  request_reader_b.reset();
  std::lock_guard<std::mutex> lock(stats_mutex);
  ++stats.clients_accepted;
}

void Lms100Emulator::Server::disconnect() {
  if (client_fd < 0) return;
  close_socket(client_fd);
  device.on_client_disconnected();
  stream_was_enabled = false;
  merge_buffer.clear();
  merged_count = 0;
  stall_buffer.clear();
  std::lock_guard<std::mutex> lock(stats_mutex);
  ++stats.disconnects;
}

void Lms100Emulator::Server::read_client() {
  uint8_t buffer[4096];
  const ssize_t n = ::recv(client_fd, buffer, sizeof(buffer), MSG_DONTWAIT);
  if (n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
    disconnect();
    return;
  }
  if (n < 0) return;
  if (!config.cola_b) {
    request_reader.feed(buffer, static_cast<size_t>(n));
    while (client_fd >= 0 && request_reader.next(request)) handle_request(request);
    return;
  }
  request_reader_b.feed(buffer, static_cast<size_t>(n));
  while (client_fd >= 0 && request_reader_b.next(binary)) {
    // A request whose arguments do not fit its layout reaches the device as non-text: sFA.
    if (!cola_b_request_to_text(binary, request)) request = binary;
    handle_request(request);
  }
}

void Lms100Emulator::Server::handle_request(const std::string& payload) {
  {
    std::lock_guard<std::mutex> lock(stats_mutex);
    ++stats.requests;
  }
  const Lms100Device::Action action = device.handle_request(payload, device_now(), reply);
  if (device.stream_enabled() && !stream_was_enabled) stream_telegrams = 0;
  stream_was_enabled = device.stream_enabled();
  if (action == Lms100Device::Action::reply_with_scan) {
    ScanSlot slot;
    if (!device.scheduler().last_scan(slot)) {
      // Nothing measured yet: the device still answers, with the current clock and counter.
      slot.start_us = device_now();
      slot.complete_us = slot.start_us;
      slot.scan_counter = device.scheduler().next_scan_counter();
    }
    emit_scan(slot, false);
    return;
  }
  if (config.cola_b) {
    cola_b_reply_from_text(reply, binary);
    reply.swap(binary);
  }
  send_frame(reply, false);
  if (settings.duplicate_replies && client_fd >= 0) send_frame(reply, false);
}

void Lms100Emulator::Server::send_frame(const std::string& payload, bool is_scan) {
  if (client_fd < 0) return;
  framed.clear();
  if (settings.junk_bytes_between_telegrams > 0) {
    append_junk_bytes(static_cast<size_t>(settings.junk_bytes_between_telegrams), rng, framed);
  }
  if (config.cola_b) {
    frame_cola_b_telegram(payload, framed);
  } else {
    framed.push_back(cola::kStx);
    framed.append(payload);
    framed.push_back(cola::kEtx);
  }

  if (is_scan && faults.take_reset_mid_telegram()) {
    flush_merged();
    const std::string half = framed.substr(0, framed.size() / 2);
    if (client_fd >= 0) send_all(client_fd, half.data(), half.size());
    disconnect();
    return;
  }
  if (is_scan && settings.merge_scan_telegrams > 1) {
    merge_buffer += framed;
    if (++merged_count >= settings.merge_scan_telegrams) flush_merged();
    return;
  }
  flush_merged();  // keep the order: scans held for merging go before this frame
  write_out(framed);
}

void Lms100Emulator::Server::flush_merged() {
  if (merge_buffer.empty()) return;
  std::string merged;
  merged.swap(merge_buffer);
  merged_count = 0;
  write_out(merged);
}

void Lms100Emulator::Server::write_out(const std::string& bytes) {
  if (client_fd < 0 || bytes.empty()) return;
  if (stalled_until_mono > 0) {
    stall_buffer += bytes;
    return;
  }
  plan_write_cuts(bytes.size(), settings, rng, cuts);
  size_t begin = 0;
  cuts.push_back(bytes.size());
  for (const size_t end : cuts) {
    if (begin > 0 && settings.split_gap_ms > 0)
      ::usleep(static_cast<useconds_t>(settings.split_gap_ms) * 1000);
    if (!send_all(client_fd, bytes.data() + begin, end - begin)) {
      disconnect();
      return;
    }
    begin = end;
  }
}

Lms100Emulator::Lms100Emulator(const Lms100EmulatorConfig& config, ScanSource source)
    : config_(config), source_(std::move(source)) {
  faults_.set_settings(config.faults);
}

Lms100Emulator::~Lms100Emulator() {
  stop();
  faults_.set_change_listener(nullptr);
  // The pipe lives as long as the object: a fault call racing with stop() still writes to a valid fd.
  close_socket(wake_pipe_[0]);
  close_socket(wake_pipe_[1]);
}

void Lms100Emulator::start() {
  if (thread_.joinable()) return;
  if (wake_pipe_[0] < 0 && ::pipe2(wake_pipe_, O_NONBLOCK | O_CLOEXEC) != 0) {
    throw std::runtime_error("pipe2() failed");
  }
  stop_requested_ = false;
  server_ = std::make_unique<Server>(config_, source_, faults_, wake_pipe_[0], stop_requested_);
  try {
    server_->listen_fd = open_listening_socket(config_.bind_address, config_.port, bound_port_);
  } catch (...) {
    server_.reset();
    throw;
  }
  server_->power_up_mono_us = monotonic_us();
  server_->power_up_utime = now_utime();
  power_up_utime_ = server_->power_up_utime;
  if (config_.refuse_first_write_after_power_up) server_->device.arm_refuse_next_write();
  const int wake_write_fd = wake_pipe_[1];
  faults_.set_change_listener([wake_write_fd] {
    const char byte = 1;
    [[maybe_unused]] const ssize_t n = ::write(wake_write_fd, &byte, 1);
  });
  thread_ = std::thread([this] { server_->run(); });
}

void Lms100Emulator::stop() {
  if (!thread_.joinable()) return;
  stop_requested_ = true;
  const char byte = 1;
  [[maybe_unused]] const ssize_t n = ::write(wake_pipe_[1], &byte, 1);
  thread_.join();
}

Lms100EmulatorStats Lms100Emulator::stats() const {
  if (!server_) return {};
  std::lock_guard<std::mutex> lock(server_->stats_mutex);
  return server_->stats;
}

}  // namespace refloc
