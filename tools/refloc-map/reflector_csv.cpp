#include "reflector_csv.hpp"

#include "common/json_config.hpp"
#include "common/reflector_map_v2_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>

namespace refloc {
namespace {

constexpr double kMaxSigma_m = 100.0;  // the map reader's largest variance is (100 m)^2

struct CsvRow {
  size_t line = 0;
  std::vector<std::string> fields;
};

struct CsvFile {
  std::string source;
  std::vector<CsvRow> rows;
  [[noreturn]] void fail(size_t line, const std::string& what) const {
    throw ConfigError(fmt::format("{}:{}: {}", source, line, what));
  }
};

std::string trimmed(const std::string& s) {
  const size_t begin = s.find_first_not_of(" \t");
  return begin == std::string::npos ? "" : s.substr(begin, s.find_last_not_of(" \t") - begin + 1);
}

// ',' separates fields, "..." quotes one (with "" for a quote), '#' outside quotes ends the line.
std::vector<std::string> split_fields(const CsvFile& file, size_t line, const std::string& text) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted && c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
      fields.back() += '"', ++i;
    } else if (c == '"' && (quoted || trimmed(fields.back()).empty())) {
      quoted = !quoted;
    } else if (!quoted && c == '#') {
      break;
    } else if (!quoted && c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  if (quoted) file.fail(line, "a quoted field is not closed");
  for (std::string& f : fields) f = trimmed(f);
  return fields;
}

CsvFile read_rows(const std::string& text, const std::string& source) {
  CsvFile file{source, {}};
  size_t begin = 0;
  for (size_t line = 1; begin < text.size(); ++line) {
    size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string content = text.substr(begin, end - begin);
    if (!content.empty() && content.back() == '\r') content.pop_back();
    begin = end + 1;
    std::vector<std::string> fields = split_fields(file, line, content);
    if (fields.size() == 1 && fields[0].empty()) continue;  // blank or comment only
    file.rows.push_back(CsvRow{line, std::move(fields)});
  }
  return file;
}

std::optional<double> parse_double(const std::string& field) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (error != std::errc() || end != field.data() + field.size() || !std::isfinite(value))
    return std::nullopt;
  return value;
}

// The column of each field: a header line names them, else id,x,y[,radius_m][,sigma_m].
std::vector<std::string> header_columns(const CsvFile& file, CsvRow& first, bool& had_header) {
  const auto& known = reflector_csv_columns();
  had_header = !parse_double(first.fields[0]).has_value();
  if (!had_header) return {known[0], known[1], known[2], known[3], known[4]};
  std::vector<std::string> columns;
  for (const std::string& name : first.fields) {
    if (std::find(known.begin(), known.end(), name) == known.end())
      file.fail(first.line, fmt::format("unknown column \"{}\" (known: {})", name, fmt::join(known, ", ")));
    if (std::find(columns.begin(), columns.end(), name) != columns.end())
      file.fail(first.line, fmt::format("column \"{}\" named twice", name));
    columns.push_back(name);
  }
  const auto has = [&](const char* name) {
    return std::find(columns.begin(), columns.end(), name) != columns.end();
  };
  for (const char* needed : {"id", "x", "y"})
    if (!has(needed)) file.fail(first.line, fmt::format("the header has no column \"{}\"", needed));
  if (has("sigma_m") && (has("sigma_x_m") || has("sigma_y_m")))
    file.fail(first.line, "give sigma_m (isotropic) or sigma_x_m and sigma_y_m, not both");
  if (has("sigma_x_m") != has("sigma_y_m") || (has("correlation_xy") && !has("sigma_x_m")))
    file.fail(first.line, "sigma_x_m and sigma_y_m go together (correlation_xy needs both)");
  return columns;
}

class RowReader {
 public:
  RowReader(const CsvFile& file, const CsvRow& row, const std::vector<std::string>& columns)
      : file_(file), row_(row) {
    for (size_t i = 0; i < columns.size() && i < row.fields.size(); ++i) values_[columns[i]] = row.fields[i];
  }
  bool has(const std::string& column) const {
    const auto it = values_.find(column);
    return it != values_.end() && !it->second.empty();
  }
  double number(const std::string& column, double min, double max, bool open_min = false) const {
    if (!has(column)) file_.fail(row_.line, fmt::format("{}: missing", column));
    const std::string& field = values_.at(column);
    const std::optional<double> v = parse_double(field);
    if (!v || *v < min || *v > max || (open_min && *v <= min)) {
      file_.fail(row_.line, fmt::format("{}: expected a number in {}{}, {}], got \"{}\"", column,
                                        open_min ? "(" : "[", min, max, field));
    }
    return *v;
  }
  const std::string& text(const std::string& column) const { return values_.at(column); }

 private:
  const CsvFile& file_;
  const CsvRow& row_;
  std::map<std::string, std::string> values_;
};

MapReflector reflector_of(const RowReader& row, const CsvImportOptions& options, const CsvFile& file,
                          size_t line) {
  MapReflector r;
  const double id = row.number("id", 0, 1e9);
  if (id != std::floor(id)) file.fail(line, fmt::format("id: expected an integer, got {}", id));
  r.id = static_cast<int>(id);
  r.map_p_center = {row.number("x", -kMaxMapCoordinate_m, kMaxMapCoordinate_m),
                    row.number("y", -kMaxMapCoordinate_m, kMaxMapCoordinate_m)};
  r.radius = row.has("radius_m") ? row.number("radius_m", 1e-3, 5.0) : options.default_radius_m;
  if (row.has("type")) r.type = row.text("type");
  if (row.has("sigma_m")) {
    const double sigma = row.number("sigma_m", 0.0, kMaxSigma_m, true);
    r.map_cov_center = Eigen::Matrix2d::Identity() * sigma * sigma;
  } else if (row.has("sigma_x_m") || row.has("sigma_y_m")) {
    const double sx = row.number("sigma_x_m", 0.0, kMaxSigma_m, true);
    const double sy = row.number("sigma_y_m", 0.0, kMaxSigma_m, true);
    const double rho = row.has("correlation_xy") ? row.number("correlation_xy", -0.999999, 0.999999) : 0.0;
    Eigen::Matrix2d cov;
    cov << sx * sx, rho * sx * sy, rho * sx * sy, sy * sy;
    r.map_cov_center = cov;
  }
  return r;
}

// The map reader's message with "/reflectors/N" turned into the CSV line of reflector N.
[[noreturn]] void rethrow_with_lines(const ConfigError& e, const std::string& source,
                                     const std::vector<size_t>& lines) {
  const std::string what = e.what();
  if (what.rfind(source + ": ", 0) != 0) throw e;
  std::string message = what.substr(source.size() + 2);
  const std::string list = "/reflectors";
  std::string leading_line;
  for (size_t at = message.find(list); at != std::string::npos; at = message.find(list, at)) {
    size_t end = at + list.size();
    size_t index = 0;
    const bool numbered =
        end < message.size() && message[end] == '/' &&
        std::from_chars(message.data() + end + 1, message.data() + message.size(), index).ec == std::errc() &&
        index < lines.size();
    if (!numbered) {  // the list as a whole: "/reflectors: expected at least 3 reflectors"
      const bool leading = at == 0 && message.compare(end, 2, ": ") == 0;
      message.replace(at, leading ? list.size() + 2 : list.size(), leading ? "" : "the CSV");
      continue;
    }
    end = message.find_first_not_of("0123456789", end + 1);
    const std::string replacement = fmt::format("line {}", lines[index]);
    if (at == 0) leading_line = std::to_string(lines[index]);
    message.replace(at, (end == std::string::npos ? message.size() : end) - at, replacement);
  }
  if (!leading_line.empty()) message = message.substr(message.find(": ") + 2);
  throw ConfigError(leading_line.empty() ? fmt::format("{}: {}", source, message)
                                         : fmt::format("{}:{}: {}", source, leading_line, message));
}

}  // namespace

const std::vector<std::string>& reflector_csv_columns() {
  static const std::vector<std::string> columns{
      "id", "x", "y", "radius_m", "sigma_m", "sigma_x_m", "sigma_y_m", "correlation_xy", "type"};
  return columns;
}

ReflectorMap import_reflector_csv(const std::string& text, const std::string& source,
                                  const CsvImportOptions& options) {
  CsvFile file = read_rows(text, source);
  if (file.rows.empty()) throw ConfigError(source + ": no reflector lines (id,x,y[,radius_m][,sigma_m])");
  bool had_header = false;
  const std::vector<std::string> columns = header_columns(file, file.rows.front(), had_header);
  ReflectorMap map;
  map.info = MapInfo{2, options.map_id, 1, iso8601_utc_now(), "imported"};
  std::vector<size_t> lines;
  std::map<int, size_t> line_of_id;
  for (size_t i = had_header ? 1 : 0; i < file.rows.size(); ++i) {
    const CsvRow& row = file.rows[i];
    const size_t max_fields = had_header ? columns.size() : 5;
    if (row.fields.size() > max_fields || (!had_header && row.fields.size() < 3)) {
      file.fail(row.line, had_header
                              ? fmt::format("{} fields, the header names {}", row.fields.size(), max_fields)
                              : fmt::format("expected id,x,y[,radius_m][,sigma_m] (3 to 5 fields), got {}",
                                            row.fields.size()));
    }
    MapReflector r = reflector_of(RowReader(file, row, columns), options, file, row.line);
    const auto [it, inserted] = line_of_id.emplace(r.id, row.line);
    if (!inserted) file.fail(row.line, fmt::format("duplicate id {} (first at line {})", r.id, it->second));
    map.reflectors.push_back(std::move(r));
    lines.push_back(row.line);
  }
  try {  // the map reader's checks: spacing, at least 3 reflectors
    const ReflectorMap checked =
        parse_reflector_map(JsonConfig::parse_text(reflector_map_v2_text(map), source));
    map.warnings = checked.warnings;
  } catch (const ConfigError& e) {
    rethrow_with_lines(e, source, lines);
  }
  return map;
}

std::string reflector_csv_text(const ReflectorMap& map) {
  std::string text = "id,x,y,radius_m,sigma_x_m,sigma_y_m,correlation_xy,type\n";
  for (const MapReflector& r : map.reflectors) {
    std::string covariance = ",,";
    if (r.map_cov_center) {
      const Eigen::Matrix2d& c = *r.map_cov_center;
      const double sx = std::sqrt(c(0, 0));
      const double sy = std::sqrt(c(1, 1));
      covariance = fmt::format("{},{},{}", sx, sy, c(0, 1) / (sx * sy));
    }
    std::string type = r.type;
    if (type.find_first_of(",\"#") != std::string::npos || trimmed(type) != type) {
      std::string escaped;
      for (const char c : type) escaped += c == '"' ? std::string("\"\"") : std::string(1, c);
      type = "\"" + escaped + "\"";
    }
    text += fmt::format("{},{},{},{},{},{}\n", r.id, r.map_p_center.x(), r.map_p_center.y(), r.radius,
                        covariance, type);
  }
  return text;
}

}  // namespace refloc
