#pragma once
// Export of chosen channels of a log: JSON lines (every field, arrays as JSON
// arrays) or CSV (flattened, see csv_flatten.hpp), one CSV file per channel.

#include "log_reader.hpp"
#include "message_json.hpp"

#include <cstdint>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <regex>
#include <string>
#include <vector>

namespace refloc {

/// Which channels to export: each pattern is a regular expression (ECMAScript)
/// that must match the whole channel name, so "POSE" selects POSE only and
/// "LASER_.*|POSE" several. No patterns selects every channel.
class ChannelSelector {
 public:
  /// Throws ConfigError for an invalid regular expression.
  explicit ChannelSelector(const std::vector<std::string>& patterns);
  bool matches(const std::string& channel) const;

 private:
  std::vector<std::regex> patterns_;
  mutable std::map<std::string, bool> cache_;
};

struct ExportCounts {
  int64_t written = 0;       ///< rows or lines written
  int64_t undecoded = 0;     ///< not a refloc type, or corrupt
  int64_t type_changed = 0;  ///< CSV only: a different type than the channel's first message
};

/// One JSON object per line: {"log_utime", "channel", "type", "msg": {...}};
/// undecodable messages: "type": null and "bytes".
class JsonlExporter {
 public:
  /// Throws ConfigError when the file cannot be written.
  JsonlExporter(const std::string& path, const MessageDecoder& decoder);
  void add(const LogEventView& event);
  const ExportCounts& counts() const { return counts_; }

 private:
  const MessageDecoder& decoder_;
  std::ofstream out_;
  std::string path_;
  ExportCounts counts_;
};

/// CSV: columns log_utime, channel, then the type's flattened fields. A channel's
/// columns come from the type of its first decodable message.
class CsvExporter {
 public:
  CsvExporter(std::function<std::string(const std::string& channel)> path_for_channel,
              const MessageDecoder& decoder);
  void add(const LogEventView& event);
  const ExportCounts& counts() const { return counts_; }
  /// Files written so far, by channel.
  std::map<std::string, std::string> files() const;

 private:
  struct ChannelFile {
    std::string path;
    std::string type;
    std::vector<std::string> columns;
    std::unique_ptr<std::ofstream> out;
  };
  std::function<std::string(const std::string&)> path_for_channel_;
  const MessageDecoder& decoder_;
  std::map<std::string, ChannelFile> files_;
  ExportCounts counts_;
};

/// `path` itself when a single channel is exported, else "<stem>_<CHANNEL><ext>"
/// next to it (out.csv -> out_POSE.csv); characters unsafe in file names become '_'.
std::string csv_path_for_channel(const std::string& path, const std::string& channel, bool single_channel);

}  // namespace refloc
