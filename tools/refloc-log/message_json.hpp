#pragma once
// Decoding of the refloc LCM types (lcmtypes/*.lcm) found in a log, chosen by
// their fingerprint (the first 8 bytes of every encoded message), into JSON
// with the fields in declaration order. float fields are written with their
// shortest float representation (0.1f -> 0.1, not 0.10000000149011612).

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace refloc {

using OrderedJson = nlohmann::ordered_json;

/// A decoded message: its type name (e.g. "pose2d_t") and fields.
struct DecodedMessage {
  std::string type;
  OrderedJson fields;
};

class MessageDecoder {
 public:
  /// Knows all 12 refloc types.
  MessageDecoder();

  /// Type name for the fingerprint at the start of data; nullptr if not a refloc type.
  const char* type_name(const uint8_t* data, size_t size) const;
  /// Full decode; nullopt for an unknown fingerprint or a truncated/corrupt message.
  std::optional<DecodedMessage> decode(const uint8_t* data, size_t size) const;
  /// The leading `int64_t utime` of every refloc type that starts with one (all but
  /// reflector_t and reflector_match_t), read without decoding the rest [us].
  std::optional<int64_t> utime(const uint8_t* data, size_t size) const;
  /// A default message of the type with one element in each array of structs, so
  /// CSV columns can be derived even when the first real message has none.
  const OrderedJson* prototype(const std::string& type) const;
  /// Names of every known type.
  std::vector<std::string> type_names() const;

 private:
  struct Type {
    std::string name;
    bool utime_first = true;
    std::function<bool(const uint8_t*, size_t, OrderedJson&)> decode;
    OrderedJson prototype;
  };
  template <class Message>
  void add(bool utime_first);
  const Type* find(const uint8_t* data, size_t size) const;

  std::vector<Type> types_;
  std::unordered_map<int64_t, size_t> by_fingerprint_;
};

}  // namespace refloc
