#include "status_table.hpp"

#include "counter_kind.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace refloc {
namespace {

std::string state_column(const ServiceStatus& s) {
  if (!s.seen) return "MISSING";
  const std::string name = heartbeat_state_name(s.last.state);
  return s.stale ? "STALE:" + name : name;
}

/// value with `decimals` if that fits `width`, else rounded, else ">" and the largest that fits.
std::string fit_number(double value, size_t width, int decimals) {
  std::string text = fmt::format("{:.{}f}", value, decimals);
  if (text.size() <= width) return text;
  text = fmt::format("{:.0f}", value);
  if (text.size() <= width) return text;
  return ">" + std::string(width - 1, '9');
}

/// Cut to width with a trailing "~" marking the cut.
std::string fit_text(const std::string& text, size_t width) {
  if (text.size() <= width) return text;
  return width == 0 ? "" : text.substr(0, width - 1) + "~";
}

std::string right_trimmed(std::string text) {
  text.erase(text.find_last_not_of(' ') + 1);
  return text;
}

std::string detail_of(const ServiceStatus& s) {
  if (!s.seen) return "no heartbeat";
  std::string detail = s.last.state_detail;
  if (s.pid_changes > 0)
    detail += fmt::format("{}(pid changed {}x)", detail.empty() ? "" : " ", s.pid_changes);
  return detail;
}

std::string joined_counters(const NamedCounters& counters) {
  std::string text;
  for (const auto& [name, value] : counters)
    text += fmt::format("{}{}={}", text.empty() ? "" : " ", name, value);
  return text;
}

/// decode_errors (when non-zero) and the non-zero error counters, as name=value.
NamedCounters errors_of(const ServiceStatus& s) {
  NamedCounters errors;
  if (s.last.decode_errors != 0) errors.emplace_back("decode_errors", s.last.decode_errors);
  for (auto& e : split_counters(s.last.counters).errors) errors.push_back(std::move(e));
  return errors;
}

// Narrow columns: 19+7+14+6+6+6+4+6 characters and 8 separators; the detail gets the rest.
constexpr const char* kNarrowRow = "{:<19} {:>7} {:<14} {:>6} {:>6} {:>6} {:>4} {:>6} {}";
constexpr size_t kNarrowDetailColumn = 19 + 7 + 14 + 6 + 6 + 6 + 4 + 6 + 8;

std::string narrow_row(const ServiceStatus& s, std::vector<const ServiceStatus*>& cut) {
  const size_t detail_width = kStatusColumns - kNarrowDetailColumn;
  const std::string detail = detail_of(s);
  if (detail.size() > detail_width) cut.push_back(&s);
  if (!s.seen)
    return fmt::format(kNarrowRow, fit_text(s.service, 19), "-", state_column(s), "-", "-", "-", "-", "-",
                       fit_text(detail, detail_width));
  const bool rates = s.has_rates();
  return fmt::format(kNarrowRow, fit_text(s.service, 19), s.last.pid, state_column(s),
                     rates ? fit_number(s.rate_in_hz, 6, 1) : "-",
                     rates ? fit_number(s.rate_out_hz, 6, 1) : "-",
                     fit_number(s.last.processing_p99_us, 6, 0), fit_number(s.age_s, 4, 1),
                     error_kinds(s.last.decode_errors, s.last.counters), fit_text(detail, detail_width));
}

constexpr const char* kWideRow = "{:<20} {:>8} {:<14} {:>8} {:>8} {:>9} {:>9} {:>6}  {:<24} {:<24} {}";

std::string wide_row(const ServiceStatus& s) {
  if (!s.seen)
    return fmt::format(kWideRow, s.service, "-", state_column(s), "-", "-", "-", "-", "-", "-", "-",
                       detail_of(s));
  const auto rate = [&](double hz) { return s.has_rates() ? fmt::format("{:.1f}", hz) : "-"; };
  const std::string errors = joined_counters(errors_of(s));
  const std::string normal = joined_counters(split_counters(s.last.counters).normal);
  return fmt::format(kWideRow, s.service, s.last.pid, state_column(s), rate(s.rate_in_hz),
                     rate(s.rate_out_hz), fmt::format("{:.0f}", s.last.processing_p50_us),
                     fmt::format("{:.0f}", s.last.processing_p99_us), fmt::format("{:.1f}", s.age_s),
                     errors.empty() ? "0" : errors, normal.empty() ? "-" : normal, detail_of(s));
}

std::string summary_lines(const std::vector<ServiceStatus>& rows) {
  std::string out;
  const auto missing = missing_services(rows);
  const size_t expected =
      std::count_if(rows.begin(), rows.end(), [](const ServiceStatus& s) { return s.expected; });
  if (missing.empty()) {
    out += fmt::format("all {} expected services alive\n", expected);
  } else {
    out += fmt::format("MISSING or stale: {}\n", fmt::join(missing, ", "));
  }
  const auto in_error = services_in_error(rows);
  if (!in_error.empty()) out += fmt::format("IN ERROR: {}\n", fmt::join(in_error, ", "));
  std::vector<std::string> twice;
  for (const auto& s : rows) {
    if (s.duplicate && (twice.empty() || twice.back() != s.service)) twice.push_back(s.service);
  }
  if (!twice.empty()) out += fmt::format("RUNNING MORE THAN ONCE: {}\n", fmt::join(twice, ", "));
  return out;
}

/// The error counters of every service that has any, one service a line (wrapped later).
std::string errors_section(const std::vector<ServiceStatus>& rows) {
  std::string out;
  for (const auto& s : rows) {
    if (!s.seen) continue;
    const std::string errors = joined_counters(errors_of(s));
    if (!errors.empty()) out += fmt::format("  {}: {}\n", s.service, errors);
  }
  return out.empty() ? "errors: none\n"
                     : "errors (non-zero error counters since each process started):\n" + out;
}

}  // namespace

std::string format_status_table(const std::vector<ServiceStatus>& rows, bool wide) {
  std::string out;
  if (wide) {
    out += fmt::format(kWideRow, "SERVICE", "PID", "STATE", "IN/s", "OUT/s", "P50[us]", "P99[us]", "AGE[s]",
                       "ERRORS", "COUNTERS", "DETAIL") +
           "\n";
    for (const auto& s : rows) out += right_trimmed(wide_row(s)) + "\n";
    return out + summary_lines(rows);
  }
  out += fmt::format(kNarrowRow, "SERVICE", "PID", "STATE", "IN/s", "OUT/s", "p99us", "AGE", "ERRORS",
                     "DETAIL") +
         "\n";
  std::vector<const ServiceStatus*> cut;
  for (const auto& s : rows) out += right_trimmed(narrow_row(s, cut)) + "\n";
  std::string below = summary_lines(rows) + errors_section(rows);
  if (!cut.empty()) {
    below += "details cut above:\n";
    for (const ServiceStatus* s : cut) below += fmt::format("  {}: {}\n", s->service, detail_of(*s));
  }
  return out + wrap_to_width(below);
}

std::string wrap_to_width(const std::string& text, size_t width) {
  const std::string indent = "    ";
  std::string out;
  size_t begin = 0;
  while (begin < text.size()) {
    size_t end = text.find('\n', begin);
    const bool newline = end != std::string::npos;
    if (!newline) end = text.size();
    std::string line = text.substr(begin, end - begin);
    bool first = true;
    while (line.size() > width) {
      size_t cut = line.rfind(' ', width);
      // No space to break at: cut the word, always past the indent so every pass makes progress.
      if (cut == std::string::npos || cut <= (first ? 0 : indent.size()))
        cut = first ? width : std::max(width, indent.size() + 1);
      out += line.substr(0, cut) + "\n";
      line = indent + line.substr(line[cut] == ' ' ? cut + 1 : cut);
      first = false;
    }
    out += line + (newline ? "\n" : "");
    begin = end + 1;
  }
  return out;
}

}  // namespace refloc
