#include "log_export.hpp"

#include "common/json_config.hpp"
#include "csv_flatten.hpp"

#include <cctype>

namespace refloc {

ChannelSelector::ChannelSelector(const std::vector<std::string>& patterns) {
  for (const auto& p : patterns) {
    try {
      patterns_.emplace_back(p, std::regex::ECMAScript);
    } catch (const std::regex_error& e) {
      throw ConfigError("--channel '" + p + "': not a valid regular expression (" + e.what() + ")");
    }
  }
}

bool ChannelSelector::matches(const std::string& channel) const {
  if (patterns_.empty()) return true;
  const auto it = cache_.find(channel);
  if (it != cache_.end()) return it->second;
  bool match = false;
  for (const auto& re : patterns_) match = match || std::regex_match(channel, re);
  cache_.emplace(channel, match);
  return match;
}

JsonlExporter::JsonlExporter(const std::string& path, const MessageDecoder& decoder)
    : decoder_(decoder), out_(path), path_(path) {
  if (!out_) throw ConfigError(path + ": cannot write");
}

void JsonlExporter::add(const LogEventView& event) {
  OrderedJson line;
  line["log_utime"] = event.log_utime;
  line["channel"] = *event.channel;
  if (auto m = decoder_.decode(event.data, event.size)) {
    line["type"] = m->type;
    line["msg"] = std::move(m->fields);
  } else {
    line["type"] = nullptr;
    line["bytes"] = event.size;
    ++counts_.undecoded;
  }
  out_ << line.dump() << '\n';
  ++counts_.written;
}

CsvExporter::CsvExporter(std::function<std::string(const std::string&)> path_for_channel,
                         const MessageDecoder& decoder)
    : path_for_channel_(std::move(path_for_channel)), decoder_(decoder) {}

void CsvExporter::add(const LogEventView& event) {
  auto message = decoder_.decode(event.data, event.size);
  if (!message) {
    ++counts_.undecoded;
    return;
  }
  auto it = files_.find(*event.channel);
  if (it == files_.end()) {
    ChannelFile f;
    f.path = path_for_channel_(*event.channel);
    f.type = message->type;
    f.columns = csv_columns(*decoder_.prototype(message->type));
    f.out = std::make_unique<std::ofstream>(f.path);
    if (!*f.out) throw ConfigError(f.path + ": cannot write");
    std::vector<std::string> header{"log_utime", "channel"};
    header.insert(header.end(), f.columns.begin(), f.columns.end());
    *f.out << csv_line(header) << '\n';
    it = files_.emplace(*event.channel, std::move(f)).first;
  }
  ChannelFile& f = it->second;
  if (message->type != f.type) {
    ++counts_.type_changed;
    return;
  }
  std::vector<std::string> cells{std::to_string(event.log_utime), *event.channel};
  auto fields = csv_cells(message->fields, f.columns);
  cells.insert(cells.end(), std::make_move_iterator(fields.begin()), std::make_move_iterator(fields.end()));
  *f.out << csv_line(cells) << '\n';
  ++counts_.written;
}

std::map<std::string, std::string> CsvExporter::files() const {
  std::map<std::string, std::string> out;
  for (const auto& [channel, f] : files_) out[channel] = f.path;
  return out;
}

std::string csv_path_for_channel(const std::string& path, const std::string& channel, bool single_channel) {
  if (single_channel) return path;
  std::string safe = channel;
  for (char& c : safe) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-' && c != '.') c = '_';
  }
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash + 1);
  if (!has_ext) return path + "_" + safe;
  return path.substr(0, dot) + "_" + safe + path.substr(dot);
}

}  // namespace refloc
