// ConsoleServer in process on a loopback port of the kernel's choice, with plain sockets as
// clients: the page is served, a client that stops reading is dropped and counted while the
// sender never waits, one over the limit is refused.

#include "web_console/console_server.hpp"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

int connect_to(uint16_t port, int receive_buffer_bytes = 0) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  if (receive_buffer_bytes > 0)
    setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &receive_buffer_bytes, sizeof receive_buffer_bytes);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  EXPECT_EQ(connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
  return fd;
}

std::string request_reply(int fd, const std::string& request) {
  EXPECT_EQ(write(fd, request.data(), request.size()), static_cast<ssize_t>(request.size()));
  const timeval timeout{2, 0};
  setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
  char buffer[512];
  const ssize_t n = read(fd, buffer, sizeof buffer);
  return n > 0 ? std::string(buffer, static_cast<size_t>(n)) : "";
}

std::string upgrade_request(uint16_t port) {
  return "GET / HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
         "\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"
         "Sec-WebSocket-Version: 13\r\n\r\n";
}

class ConsoleServerTest : public ::testing::Test {
 protected:
  void start(ConsoleServerConfig config) {
    config.port = 0;
    std::map<std::string, WwwFile> files = {{"/", {"text/html", "<p>console</p>"}}};
    server_ = std::make_unique<ConsoleServer>(config, RequestValidator({}, 1024), files);
    server_->start();
  }
  int64_t counter(const std::string& name) { return server_->counters()[name]; }
  std::unique_ptr<ConsoleServer> server_;
};

TEST_F(ConsoleServerTest, ServesThePageAndNothingElse) {
  start({});
  const int page = connect_to(server_->port());
  EXPECT_NE(request_reply(page, "GET / HTTP/1.1\r\nHost: x\r\n\r\n").find("200 OK"), std::string::npos);
  close(page);
  const int other = connect_to(server_->port());
  EXPECT_NE(request_reply(other, "GET /../etc/passwd HTTP/1.1\r\nHost: x\r\n\r\n").find("404"),
            std::string::npos);
  close(other);
  EXPECT_EQ(counter("http_not_found"), 1);
}

TEST_F(ConsoleServerTest, AClientThatStopsReadingIsDroppedAndTheSenderNeverWaits) {
  ConsoleServerConfig config;
  config.stalled_client_timeout_s = 0.3;
  config.client_queue_frames = 32;
  start(config);
  const int silent = connect_to(server_->port(), 4096);
  ASSERT_NE(request_reply(silent, upgrade_request(server_->port())).find("101"), std::string::npos);
  const ConsoleFrame frame{"", true, std::make_shared<const std::string>(std::string(256 * 1024, 'x'))};
  const auto begin = std::chrono::steady_clock::now();
  double slowest_send_s = 0.0;
  for (int i = 0; i < 400 && counter("clients_dropped_stalled") == 0; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    server_->send(frame);
    slowest_send_s = std::max(slowest_send_s,
                              std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_EQ(counter("clients_dropped_stalled"), 1);
  EXPECT_GT(counter("frames_dropped"), 0);
  EXPECT_EQ(counter("clients"), 0);
  EXPECT_LT(slowest_send_s, 0.01) << "send() waited for the client";
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count(), 4.0);
  close(silent);
}

TEST_F(ConsoleServerTest, OneClientOverTheLimitIsRefused) {
  ConsoleServerConfig config;
  config.max_clients = 1;
  start(config);
  const int first = connect_to(server_->port());
  ASSERT_NE(request_reply(first, upgrade_request(server_->port())).find("101"), std::string::npos);
  const int second = connect_to(server_->port());
  EXPECT_NE(request_reply(second, upgrade_request(server_->port())).find("503"), std::string::npos);
  EXPECT_EQ(counter("clients_refused_limit"), 1);
  close(first);
  close(second);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
