// libFuzzer entry: arbitrary bytes through the CoLa-B decoder and the CoLa-A
// splitter, then every CoLa-A payload through the LMDscandata parser, the LaserScan conversion and the
// reply checks. The data is also parsed as one payload directly, so the parser
// sees inputs that contain neither STX nor ETX.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "common/laser_scan.hpp"
#include "lms100_driver/cola_a_commands.hpp"
#include "lms100_driver/cola_a_splitter.hpp"
#include "lms100_driver/cola_b_scandata_parser.hpp"
#include "lms100_driver/lmd_scandata_parser.hpp"
#include "lms100_driver/scan_conversion.hpp"

namespace {

void parse_payload(std::string_view payload, refloc::LmdScanData& data, refloc::LaserScan& scan) {
  if (refloc::parse_lmd_scandata(payload, data).ok()) (void)refloc::to_laser_scan(data, scan);
  uint32_t value = 0;
  (void)refloc::parse_status_reply(payload, value);
  (void)refloc::parse_device_state_reply(payload, value);
  (void)refloc::check_scan_config_reply(payload, refloc::ScanConfig{});
  (void)refloc::check_login_reply(payload);
  if (refloc::parse_sopas_error(payload, value)) (void)refloc::sopas_error_name(value);
  (void)refloc::is_reply_to("sMN Run", payload);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  refloc::LmdScanData parsed;
  refloc::LaserScan scan;
  const std::string_view whole(reinterpret_cast<const char*>(data), size);
  parse_payload(whole, parsed, scan);
  // The same bytes as a CoLa-B frame and as a CoLa-B payload.
  std::string_view binary_payload;
  if (refloc::unframe_cola_b(whole, binary_payload).ok())
    (void)refloc::parse_lmd_scandata_cola_b(binary_payload, parsed);
  if (refloc::parse_lmd_scandata_cola_b(whole, parsed).ok()) (void)refloc::to_laser_scan(parsed, scan);

  refloc::ColaASplitter splitter(4096);
  // Feed in two pieces so split reads are exercised too.
  const size_t half = size / 2;
  splitter.feed(data, half);
  std::string payload;
  while (splitter.next(payload)) parse_payload(payload, parsed, scan);
  splitter.feed(data + half, size - half);
  while (splitter.next(payload)) parse_payload(payload, parsed, scan);
  return 0;
}
