#pragma once
// The few POSIX TCP calls the emulator needs, with errors turned into exceptions
// (at start-up) or false (per connection, where a failure only drops the client).

#include <cstddef>
#include <cstdint>
#include <string>

namespace refloc {

/// Listening socket on address:port (port 0 = ephemeral); bound_port receives the
/// port actually bound. Throws std::runtime_error with the reason on failure.
int open_listening_socket(const std::string& address, uint16_t port, uint16_t& bound_port);

/// Accepts one pending connection; -1 if none (the listening socket is non-blocking).
int accept_client(int listen_fd);

/// TCP_NODELAY (each write leaves as its own segment, which the split fault relies on)
/// and a send timeout so a client that stops reading cannot block the emulator forever.
void configure_client_socket(int fd, int send_timeout_ms);

/// Sends every byte (blocking, no SIGPIPE); false when the peer is gone or too slow.
bool send_all(int fd, const char* data, size_t size);

/// Closes fd if it is open and sets it to -1.
void close_socket(int& fd);

}  // namespace refloc
