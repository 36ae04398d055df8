#pragma once
// The emulated device's side of CoLa-A framing: cuts the host's byte stream into request
// payloads the way an LMS100 does (bytes outside STX..ETX ignored, an STX restarts the
// request, a request longer than the device's buffer dropped). Written apart from the
// driver's ColaASplitter on purpose: the emulator is the driver's test oracle.

#include "common/cola_a_framing.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace refloc {

class ColaARequestReader {
 public:
  /// max_request_bytes: a request payload longer than this is dropped [bytes].
  explicit ColaARequestReader(size_t max_request_bytes = cola::kMaxTelegramBytes)
      : max_request_bytes_(max_request_bytes) {}

  /// Appends received bytes.
  void feed(const uint8_t* data, size_t size);
  /// Pops the next complete request payload (without STX/ETX); false if none is complete.
  bool next(std::string& payload);
  /// Forgets buffered bytes and any open request (a new client connected).
  void reset();

 private:
  size_t max_request_bytes_;
  std::string received_;  ///< bytes fed and not yet examined from read_pos_ on
  size_t read_pos_ = 0;
  std::string request_;      ///< payload of the open request
  bool open_ = false;        ///< an STX was seen and no ETX yet
  bool overflowed_ = false;  ///< the open request outgrew max_request_bytes_
};

}  // namespace refloc
