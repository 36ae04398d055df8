#include "reflector_matcher/matcher_node.hpp"

#include <utility>

namespace refloc {

MatcherNode::MatcherNode(ReflectorMap map, const MatcherServiceConfig& config, const Pose2& robot_T_laser)
    : matcher_(std::move(map), config.matcher), selector_(config.prior, robot_T_laser) {}

const MatcherOutput& MatcherNode::on_detections(int64_t utime,
                                                const std::vector<ReflectorDetection>& detections) {
  output_.utime = utime;
  const PriorChoice choice = selector_.select(utime);
  output_.prior_source = choice.source;
  matcher_.match(detections, choice.prior ? &*choice.prior : nullptr, output_.result);
  output_.startup_event = selector_.on_result(utime, output_.result);
  return output_;
}

}  // namespace refloc
