#pragma once
// Flattening a decoded message into CSV cells, one column per scalar:
//  - nested structs:       "detection.x"
//  - arrays of numbers or strings (ranges, covariance, counter_names): one cell,
//    elements joined by ';'
//  - arrays of structs (reflectors, matches): one column per scalar field of the
//    element ("reflectors.range"), the elements' values joined by ';'; arrays
//    inside those elements (reflectors.covariance) are omitted: the count column
//    (nreflectors) stays, and --jsonl keeps everything.
// Columns come from the type's prototype (MessageDecoder::prototype).

#include "message_json.hpp"

#include <string>
#include <vector>

namespace refloc {

/// Column names of a message type, in field declaration order.
std::vector<std::string> csv_columns(const OrderedJson& prototype);

/// Cells of one message for the given columns (empty where a column has no value).
std::vector<std::string> csv_cells(const OrderedJson& message, const std::vector<std::string>& columns);

/// One CSV line (RFC 4180 quoting where needed), without the newline.
std::string csv_line(const std::vector<std::string>& cells);

}  // namespace refloc
