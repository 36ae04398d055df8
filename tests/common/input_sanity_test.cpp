#include "common/input_sanity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(InputSanity, NaNAndInfinityFailEveryCheck) {
  EXPECT_FALSE(all_finite({1.0, kNaN}));
  EXPECT_FALSE(all_finite({kInf}));
  EXPECT_TRUE(all_finite({1.0, -1e300}));
  EXPECT_FALSE(finite_within(kNaN, -1.0, 1.0));
  EXPECT_FALSE(finite_within(kInf, -kInf, kInf));
  EXPECT_FALSE(finite_abs_at_most(kNaN, 1.0));
  EXPECT_TRUE(finite_within(0.5, 0.0, 1.0));
  EXPECT_FALSE(finite_abs_at_most(1e300, 1e6));
}

TEST(InputSanity, ACovarianceMustBeFiniteSymmetricPsdAndBounded) {
  Eigen::Matrix3d c = Eigen::Vector3d(1e-4, 1e-4, 1e-5).asDiagonal();
  EXPECT_TRUE(is_usable_covariance(c, 1e4));
  EXPECT_TRUE(is_usable_covariance(Eigen::Matrix3d::Zero(), 1e4));
  Eigen::Matrix3d nan = c;
  nan(1, 2) = kNaN;
  EXPECT_FALSE(is_usable_covariance(nan, 1e4));
  Eigen::Matrix3d asymmetric = c;
  asymmetric(0, 1) = 5e-5;
  EXPECT_FALSE(is_usable_covariance(asymmetric, 1e4));
  Eigen::Matrix3d negative = c;
  negative(2, 2) = -1e-5;
  EXPECT_FALSE(is_usable_covariance(negative, 1e4));
  Eigen::Matrix3d indefinite = c;
  indefinite(0, 1) = indefinite(1, 0) = 1e-3;  // |correlation| > 1
  EXPECT_FALSE(is_usable_covariance(indefinite, 1e4));
  EXPECT_FALSE(is_usable_covariance(c * 1e9, 1e4));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
