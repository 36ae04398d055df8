#pragma once
// JSON configuration files with validation. Every reader call names the key by
// its JSON pointer so an error message can say exactly what is wrong and where:
//   "deploy/config/robot.json: /wheel_radius_m: expected a number in [0.01, 1], got -3"

#include <nlohmann/json.hpp>

#include <limits>
#include <memory>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace refloc {

/// A config or input file that cannot be used; what() names file, key and expectation.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The largest config or map file read [bytes]: a map of 100,000 reflectors written compactly
/// is about 3 MB; anything larger is a mistake (or /dev/zero behind a symlink), not a map.
inline constexpr size_t kMaxConfigFileBytes = 4u << 20;
/// The deepest nesting of objects and arrays accepted; our files need 4 levels. Deeper files
/// are refused while parsing, before any recursive code sees them.
inline constexpr int kMaxConfigNestingDepth = 32;

/// A key as a reader asks for it: the JSON pointer and, for the parameter reference
/// (--print-config, docs/parameters.md), its unit and what it means to a user:
///   config.number({"/wheel_radius_m", "m", "radius of a wheel at its rollers"}, 0.05, 0.01, 1.0)
/// A bare pointer (maps, test data) records the key without documentation.
struct ConfigKey {
  ConfigKey(const char* pointer) : pointer(pointer) {}             // NOLINT: implicit on purpose
  ConfigKey(std::string pointer) : pointer(std::move(pointer)) {}  // NOLINT
  ConfigKey(std::string pointer, std::string unit, std::string meaning)
      : pointer(std::move(pointer)), unit(std::move(unit)), meaning(std::move(meaning)) {}
  std::string pointer;
  std::string unit;     ///< "m", "mm", "s", "Hz", "rad", "deg", "count"...; "" when none
  std::string meaning;  ///< one line: what it does and when to change it
};

/// One key as a reader asked for it and what it got: a line of the parameter reference.
struct ConfigKeyRecord {
  std::string pointer;  ///< full pointer (a child config's prefix included)
  std::string unit;
  std::string meaning;
  std::string type;   ///< number, integer, boolean, string, choice, array, object
  std::string range;  ///< "[0.01, 1]", "(0, 10]", "one of \"a\", \"b\"", "" when unbounded
  bool required = false;
  nlohmann::json default_value;  ///< null when required or not recorded
  nlohmann::json value;          ///< the effective value (the file's, else the default)
};

class JsonConfig {
 public:
  /// Parse a file; throws ConfigError when it cannot be read or is not JSON. Only a regular
  /// file of at most kMaxConfigFileBytes is read (a FIFO, a device or a directory is refused
  /// without blocking), nested at most kMaxConfigNestingDepth deep.
  static JsonConfig load_file(const std::string& path);
  /// The same checks on text already in memory; source names it in messages.
  static JsonConfig parse_text(const std::string& text, const std::string& source);
  /// Wrap a document already in memory; source names it in messages.
  JsonConfig(nlohmann::json document, std::string source);

  const std::string& source() const { return source_; }
  const nlohmann::json& document() const { return document_; }
  bool has(const std::string& pointer) const;

  /// Optional finite number in [min, max]; default when the key is absent.
  double number(const ConfigKey& key, double default_value, double min = -std::numeric_limits<double>::max(),
                double max = std::numeric_limits<double>::max()) const;
  /// Required finite number in [min, max].
  double required_number(const ConfigKey& key, double min = -std::numeric_limits<double>::max(),
                         double max = std::numeric_limits<double>::max()) const;
  /// Optional finite number in (0, max]: for sigmas, tolerances, radii and rates where 0 would
  /// silently disable what the key configures; zero_means says what 0 would do, for the message.
  double positive_number(const ConfigKey& key, double default_value, double max,
                         const std::string& zero_means) const;
  long long integer(const ConfigKey& key, long long default_value,
                    long long min = std::numeric_limits<long long>::min(),
                    long long max = std::numeric_limits<long long>::max()) const;
  long long required_integer(const ConfigKey& key, long long min = std::numeric_limits<long long>::min(),
                             long long max = std::numeric_limits<long long>::max()) const;
  bool boolean(const ConfigKey& key, bool default_value) const;
  std::string string(const ConfigKey& key, const std::string& default_value) const;
  /// One of the allowed values.
  std::string choice(const ConfigKey& key, const std::string& default_value,
                     const std::set<std::string>& allowed) const;
  /// Number of elements of a required array (which may be empty).
  size_t array_size(const ConfigKey& key, bool required = true) const;

  /// A sub-document the caller validates itself; it counts as known.
  const nlohmann::json& subtree(const std::string& pointer) const;
  /// The object at pointer ({} when absent) as a config of its own whose reader calls land in
  /// this config's key records with the pointer as prefix; the subtree counts as known here.
  JsonConfig child(const std::string& pointer) const;

  /// Every key a reader asked for, in first-call order: the parameter reference.
  const std::vector<ConfigKeyRecord>& key_records() const { return records_->keys; }

  /// Throws for any key in the document that no reader call asked for, so a
  /// misspelt key is an error rather than a silently ignored setting; an unknown key whose
  /// value is {} or [] is as unknown as one holding a number. Iterative: no recursion on
  /// the document's depth.
  void reject_unknown_keys() const;

  /// Throws ConfigError "<source>: <pointer>: <what>".
  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const;

 private:
  const nlohmann::json* find(const std::string& pointer) const;
  void mark_used(const std::string& pointer) const;
  /// Whether a reader asked for this pointer or for a key below it.
  bool is_known_container(const std::string& pointer) const;
  double checked_number(const std::string& pointer, const nlohmann::json& value, double min,
                        double max) const;
  long long checked_integer(const std::string& pointer, const nlohmann::json& value, long long min,
                            long long max) const;
  std::string checked_string(const std::string& pointer, const std::string& default_value) const;
  void record(const ConfigKey& key, const char* type, std::string range, bool required,
              nlohmann::json default_value, nlohmann::json value) const;

  nlohmann::json document_;
  std::string source_;
  mutable std::set<std::string> used_;
  mutable std::set<std::string> used_whole_;
  std::string record_prefix_;
  struct Records {
    std::vector<ConfigKeyRecord> keys;
    std::unordered_map<std::string, size_t> index;  // pointer -> keys[]
  };
  std::shared_ptr<Records> records_ = std::make_shared<Records>();
};

}  // namespace refloc
