#include "csv_flatten.hpp"

#include <map>

namespace refloc {
namespace {

std::string join_path(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

bool is_struct_array(const OrderedJson& value) {
  return value.is_array() && !value.empty() && value.front().is_object();
}

std::string scalar_text(const OrderedJson& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_null()) return "";  // NaN and infinities arrive as null
  return value.dump();
}

std::string joined(const OrderedJson& array) {
  std::string text;
  for (size_t i = 0; i < array.size(); ++i) {
    if (i > 0) text += ';';
    text += scalar_text(array[i]);
  }
  return text;
}

void collect_columns(const OrderedJson& object, const std::string& prefix, bool in_array,
                     std::vector<std::string>& columns) {
  for (const auto& [key, value] : object.items()) {
    const std::string path = join_path(prefix, key);
    if (value.is_object()) {
      collect_columns(value, path, in_array, columns);
    } else if (value.is_array()) {
      if (in_array) continue;  // an array inside an array element: omitted (documented)
      if (is_struct_array(value)) {
        collect_columns(value.front(), path, true, columns);
      } else {
        columns.push_back(path);
      }
    } else {
      columns.push_back(path);
    }
  }
}

void collect_cells(const OrderedJson& object, const std::string& prefix, bool in_array,
                   std::map<std::string, std::string>& cells) {
  for (const auto& [key, value] : object.items()) {
    const std::string path = join_path(prefix, key);
    if (value.is_object()) {
      collect_cells(value, path, in_array, cells);
    } else if (value.is_array()) {
      if (in_array) continue;
      if (is_struct_array(value)) {
        // Element i's value of each field becomes the i-th ';'-separated entry of its column.
        for (size_t i = 0; i < value.size(); ++i) {
          std::map<std::string, std::string> element;
          collect_cells(value[i], path, true, element);
          for (const auto& [column, text] : element) {
            std::string& cell = cells[column];
            if (i > 0) cell += ';';
            cell += text;
          }
        }
      } else {
        cells[path] = joined(value);
      }
    } else {
      cells[path] = scalar_text(value);
    }
  }
}

}  // namespace

std::vector<std::string> csv_columns(const OrderedJson& prototype) {
  std::vector<std::string> columns;
  collect_columns(prototype, "", false, columns);
  return columns;
}

std::vector<std::string> csv_cells(const OrderedJson& message, const std::vector<std::string>& columns) {
  std::map<std::string, std::string> by_column;
  collect_cells(message, "", false, by_column);
  std::vector<std::string> cells;
  cells.reserve(columns.size());
  for (const auto& c : columns) {
    const auto it = by_column.find(c);
    cells.push_back(it == by_column.end() ? std::string() : it->second);
  }
  return cells;
}

std::string csv_line(const std::vector<std::string>& cells) {
  std::string line;
  for (size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) line += ',';
    const std::string& c = cells[i];
    if (c.find_first_of(",\"\r\n") == std::string::npos) {
      line += c;
      continue;
    }
    line += '"';
    for (char ch : c) {
      if (ch == '"') line += '"';
      line += ch;
    }
    line += '"';
  }
  return line;
}

}  // namespace refloc
