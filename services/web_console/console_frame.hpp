#pragma once
// A frame for the page: one JSON text sent over the WebSocket, shared by every client's queue.

#include <memory>
#include <string>

namespace refloc {

struct ConsoleFrame {
  /// The frame is kept under this key and sent first to a client that connects later (the map,
  /// the latest pose, one per service's heartbeat); "" = not kept.
  std::string latest_key;
  /// Sent to the clients connected now; false: only kept for later clients (trail snapshots).
  bool send_now = true;
  std::shared_ptr<const std::string> text;
};

}  // namespace refloc
