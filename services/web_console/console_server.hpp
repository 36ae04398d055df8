#pragma once
// The console's HTTP and WebSocket server (Boost.Beast, kept out of this header): its own thread
// and io_context. GET serves the page's files from memory; a WebSocket upgrade is judged by the
// Origin rule and the client limit, then gets every kept frame (ConsoleFrame::latest_key) and
// from then on every frame sent. The LCM thread calls send() and take_commands(); both only take
// a short lock, never wait for a client: each client has a bounded ClientQueue, a frame beyond
// it is dropped and counted, and a client whose write stays pending for the stall timeout is
// disconnected. Client messages are judged by RequestValidator; accepted commands wait in a
// bounded inbox for the LCM loop. Every refusal is counted by reason (counters()).

#include "web_console/client_request.hpp"
#include "web_console/console_config.hpp"
#include "web_console/console_frame.hpp"
#include "web_console/www_files.hpp"

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace refloc {

class ConsoleServer {
 public:
  ConsoleServer(const ConsoleServerConfig& config, const RequestValidator& validator,
                std::map<std::string, WwwFile> files);
  ~ConsoleServer();
  ConsoleServer(const ConsoleServer&) = delete;
  ConsoleServer& operator=(const ConsoleServer&) = delete;

  /// Binds and starts the server thread; throws std::runtime_error naming address and port
  /// when it cannot listen (address in use, not an address of this computer).
  void start();
  /// The port listened on (the configured one; the kernel's choice when it was 0, for tests).
  uint16_t port() const;
  /// Closes every connection and joins the thread (also done by the destructor).
  void stop();

  /// From the LCM thread: keep the frame under its latest_key and queue it for every client.
  void send(const ConsoleFrame& frame);
  /// From the LCM thread: the accepted commands waiting, oldest first (the inbox is emptied).
  std::vector<ConsoleCommand> take_commands();
  /// The counters (heartbeat names) and the gauge "clients" (connected now).
  std::map<std::string, int64_t> counters() const;

  struct Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace refloc
