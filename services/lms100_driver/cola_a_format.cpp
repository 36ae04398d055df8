#include "lms100_driver/cola_a_format.hpp"

namespace refloc {

std::string frame_cola_a(const std::string& payload) {
  std::string framed;
  framed.reserve(payload.size() + 2);
  framed.push_back(cola::kStx);
  framed += payload;
  framed.push_back(cola::kEtx);
  return framed;
}

}  // namespace refloc
