// Perpendicular sections of a segmented tube (src/centerline/TubeSections): measured against a cylinder's
// exact diameter, perimeter and area, at isotropic and anisotropic spacing.
#include "centerline/TubeSections.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using medial::BinaryVolume;

// A cylinder of `radius` mm along z through the middle of the volume, voxels inside when their centre is.
BinaryVolume cylinder(double radius, const Eigen::Vector3d& spacing, int length) {
  BinaryVolume volume;
  volume.spacing = spacing;
  volume.size = {int(std::ceil(4 * radius / spacing.x())) + 1, int(std::ceil(4 * radius / spacing.y())) + 1,
                 length};
  volume.inside.assign(size_t(volume.voxelCount()), 0);
  const double cx = 0.5 * (volume.size[0] - 1) * spacing.x(), cy = 0.5 * (volume.size[1] - 1) * spacing.y();
  for (int k = 0; k < volume.size[2]; ++k)
    for (int j = 0; j < volume.size[1]; ++j)
      for (int i = 0; i < volume.size[0]; ++i)
        if (std::hypot(i * spacing.x() - cx, j * spacing.y() - cy) <= radius)
          volume.inside[size_t(volume.index(i, j, k))] = 1;
  return volume;
}

std::vector<Eigen::Vector3d> axisOf(const BinaryVolume& volume) {
  const double cx = 0.5 * (volume.size[0] - 1) * volume.spacing.x(),
               cy = 0.5 * (volume.size[1] - 1) * volume.spacing.y();
  const double z0 = 5 * volume.spacing.z(), z1 = (volume.size[2] - 6) * volume.spacing.z();
  return {Eigen::Vector3d(cx, cy, z0), Eigen::Vector3d(cx, cy, z1)};
}

void expectCylinder(const medial::TubeSections& sections, double radius, double tolerance) {
  ASSERT_FALSE(sections.arcLength.empty());
  for (size_t n = 0; n < sections.arcLength.size(); ++n) {
    EXPECT_NEAR(sections.minDiameter[n], 2 * radius, tolerance * 2 * radius) << "section " << n;
    EXPECT_NEAR(sections.maxDiameter[n], 2 * radius, tolerance * 2 * radius) << "section " << n;
    EXPECT_NEAR(sections.perimeter[n], 2 * M_PI * radius, tolerance * 2 * M_PI * radius) << "section " << n;
    EXPECT_NEAR(sections.area[n], M_PI * radius * radius, 2 * tolerance * M_PI * radius * radius)
        << "section " << n;
  }
}

}  // namespace

TEST(TubeSections, CylinderIsotropic) {
  const BinaryVolume volume = cylinder(6.0, Eigen::Vector3d(0.5, 0.5, 0.5), 80);
  medial::SectionParameters parameters;
  parameters.spacing = 2.0;
  const medial::TubeSections sections = medial::tubeSections(volume, axisOf(volume), parameters);
  EXPECT_EQ(sections.rays, 72);
  EXPECT_EQ(sections.arcLength.size(), 18u);  // 34.5 mm of axis, a section every 2 mm from 0
  expectCylinder(sections, 6.0, 0.05);
}

TEST(TubeSections, CylinderAnisotropic) {
  const BinaryVolume volume = cylinder(5.0, Eigen::Vector3d(0.7, 0.7, 1.5), 40);
  const medial::TubeSections sections = medial::tubeSections(volume, axisOf(volume));
  expectCylinder(sections, 5.0, 0.06);
  // The unfolded wall: every ray found the wall near the radius.
  for (const auto& wall : sections.wall)
    for (double distance : wall) EXPECT_NEAR(distance, 5.0, 0.4);
}

TEST(TubeSections, RaysThatLeaveTheVolumeGiveNaN) {
  BinaryVolume volume = cylinder(5.0, Eigen::Vector3d(1, 1, 1), 20);
  std::fill(volume.inside.begin(), volume.inside.end(), 1);  // no wall anywhere
  medial::SectionParameters parameters;
  parameters.maxRadius = 8;  // the volume's half width is 10: no crossing within 8 mm
  const medial::TubeSections sections = medial::tubeSections(volume, axisOf(volume), parameters);
  ASSERT_FALSE(sections.arcLength.empty());
  EXPECT_TRUE(std::isnan(sections.area[0]));
  EXPECT_TRUE(std::isnan(sections.wall[0][0]));
}

TEST(TubeSections, DegenerateInputsGiveNothing) {
  const BinaryVolume volume = cylinder(5.0, Eigen::Vector3d(1, 1, 1), 20);
  EXPECT_TRUE(medial::tubeSections(volume, {}).arcLength.empty());
  EXPECT_TRUE(
      medial::tubeSections(volume, {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 1, 1)}).arcLength.empty());
  // Abort through the progress callback.
  EXPECT_TRUE(
      medial::tubeSections(volume, axisOf(volume), {}, [](double) { return false; }).arcLength.empty());
}
