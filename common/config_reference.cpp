#include "common/config_reference.hpp"

#include <fmt/format.h>

#include <memory>

namespace refloc {
namespace {

std::string trimmed(const std::string& text) {
  const size_t begin = text.find_first_not_of(' ');
  return begin == std::string::npos ? "" : text.substr(begin);
}

std::string default_text(const ConfigKeyRecord& key) {
  if (key.required) return "required";
  if (key.default_value.is_null()) return "";
  return key.default_value.dump();
}

// "meaning [unit]; number in [a, b]; default 0.05": one comment line per key.
std::string describe(const ConfigKeyRecord& key) {
  std::string text = key.meaning.empty() ? "(undocumented)" : key.meaning;
  if (!key.unit.empty()) text += " [" + key.unit + "]";
  text += "; " + key.type;
  if (!key.range.empty()) text += " " + trimmed(key.range);
  const std::string def = default_text(key);
  if (!def.empty()) text += key.required ? "; required" : "; default " + def;
  return text;
}

// Keys as a tree in first-read order; array elements' keys ("*") document their array.
struct Node {
  std::string name;
  const ConfigKeyRecord* key = nullptr;
  std::vector<const ConfigKeyRecord*> element_keys;
  std::vector<std::unique_ptr<Node>> children;
  Node* child(const std::string& child_name) {
    for (auto& c : children)
      if (c->name == child_name) return c.get();
    children.push_back(std::make_unique<Node>());
    children.back()->name = child_name;
    return children.back().get();
  }
};

std::vector<std::string> segments(const std::string& pointer) {
  std::vector<std::string> out;
  for (size_t begin = 0; begin < pointer.size();) {
    const size_t end = std::min(pointer.find('/', begin + 1), pointer.size());
    std::string s = pointer.substr(begin + 1, end - begin - 1);
    // RFC 6901 unescaping, so the printed key is the key in the file.
    for (size_t pos = 0; (pos = s.find("~1", pos)) != std::string::npos;) s.replace(pos, 2, "/");
    for (size_t pos = 0; (pos = s.find("~0", pos)) != std::string::npos;) s.replace(pos, 2, "~");
    out.push_back(std::move(s));
    begin = end;
  }
  return out;
}

void print(const Node& node, int depth, std::string& out) {
  const std::string indent(static_cast<size_t>(2 * depth), ' ');
  out += "{\n";
  for (size_t i = 0; i < node.children.size(); ++i) {
    const Node& c = *node.children[i];
    const std::string inner(static_cast<size_t>(2 * depth + 2), ' ');
    if (c.key) out += inner + "// " + describe(*c.key) + "\n";
    for (const ConfigKeyRecord* e : c.element_keys)
      out += inner + "//   " + e->pointer + ": " + describe(*e) + "\n";
    out += inner + nlohmann::json(c.name).dump() + ": ";
    if (c.key && c.children.empty())
      out += c.key->value.dump();
    else
      print(c, depth + 1, out);
    out += i + 1 < node.children.size() ? ",\n" : "\n";
  }
  out += indent + "}";
}

}  // namespace

std::string annotated_config_text(const std::vector<ConfigKeyRecord>& keys, const std::string& heading) {
  Node root;
  for (const ConfigKeyRecord& key : keys) {
    Node* node = &root;
    bool in_array = false;
    for (const std::string& s : segments(key.pointer)) {
      if (s == "*") {
        node->element_keys.push_back(&key);
        in_array = true;
        break;
      }
      node = node->child(s);
    }
    if (!in_array) node->key = &key;
  }
  std::string out;
  for (size_t begin = 0; begin < heading.size();) {
    const size_t end = std::min(heading.find('\n', begin), heading.size());
    out += "// " + heading.substr(begin, end - begin) + "\n";
    begin = end + 1;
  }
  print(root, 0, out);
  return out + "\n";
}

std::string config_reference_markdown(const std::vector<ConfigKeyRecord>& keys) {
  const auto cell = [](std::string text) {
    for (size_t pos = 0; (pos = text.find('|', pos)) != std::string::npos; pos += 2)
      text.replace(pos, 1, "\\|");
    return text;
  };
  std::string out = "| key | type | unit | default | range | meaning |\n|---|---|---|---|---|---|\n";
  for (const ConfigKeyRecord& key : keys) {
    const std::string def = default_text(key);
    out += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", cell(key.pointer), key.type, cell(key.unit),
                       def.empty() ? "" : "`" + cell(def) + "`", cell(trimmed(key.range)), cell(key.meaning));
  }
  return out;
}

std::vector<std::string> undocumented_keys(const std::vector<ConfigKeyRecord>& keys) {
  std::vector<std::string> out;
  for (const ConfigKeyRecord& key : keys)
    if (key.meaning.empty()) out.push_back(key.pointer);
  return out;
}

}  // namespace refloc
