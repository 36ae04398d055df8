#include "reflector_matcher/reflector_matcher.hpp"

namespace refloc {

ReflectorMatcher::ReflectorMatcher(ReflectorMap map, const MatcherConfig& config)
    : map_(std::move(map)), config_(config), grid_(map_, 0.5 * config.max_range) {
  if (config_.mode == MatcherMode::kPaper) {
    paper_ = std::make_unique<PaperTriangleMatcher>(map_, config_);
    return;
  }
  index_ = std::make_unique<MapTriangleIndex>(map_, config_.triangle_side_tolerance, config_.min_triangle_side,
                                              config_.max_triangle_side,
                                              static_cast<size_t>(config_.max_index_triangles));
  relocalizer_ = std::make_unique<GlobalRelocalizer>(map_, grid_, *index_, config_);
  tracker_ = std::make_unique<TrackingAssociator>(map_, grid_, config_);
}

size_t ReflectorMatcher::indexed_triangles() const { return paper_ ? paper_->map_triangles() : index_->size(); }

void ReflectorMatcher::match(const std::vector<ReflectorDetection>& detections, const PosePrior* prior,
                             MatchResult& result) {
  if (paper_) {
    paper_->match(detections, result);
    return;
  }
  if (prior != nullptr && tracker_->associate(detections, *prior, result)) return;
  relocalizer_->relocalize(detections, result);
}

}  // namespace refloc
