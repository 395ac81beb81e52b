#include "centerline/TskCenterline.h"

#include "centerline/Branches.h"
#include "centerline/TubularClusters.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace medial {

namespace {

template <class T>
int64_t selectVoxels(const T* values, int components, const TskCenterlineParameters& p, BinaryVolume& out) {
  int64_t selected = 0;
  const int64_t count = out.voxelCount();
  for (int64_t i = 0; i < count; ++i) {
    const double v = double(values[i * components]);
    bool in = v != 0;
    if (p.selection == VoxelSelection::Label) in = v == p.label;
    if (p.selection == VoxelSelection::Threshold) in = v >= p.thresholdLow && v <= p.thresholdHigh;
    out.inside[size_t(i)] = in;
    selected += in;
  }
  return selected;
}

bool dropsBorderParts(const TskCenterlineParameters& p) {
  if (p.borderParts == BorderParts::Automatic) return p.selection == VoxelSelection::Threshold;
  return p.borderParts == BorderParts::Drop;
}

std::string format(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// Phase I and II along one tube (the paper).
bool followTube(const BinaryVolume& volume, int64_t seed, const TskParameters& p,
                const std::function<bool(double)>& progress, TskCenterlineResult& result) {
  const TubularClusters clusters = structureTube(volume, seed, progress);
  if (!clusters.ok()) {
    result.error = clusters.error;
    return false;
  }
  result.primitiveCenterlinePoints = int(clusters.primitive.size());
  result.branches = {tskAxis(volume, clusters, p)};
  result.parent = {-1};
  return true;
}

// Phase I and II along every branch of a tree (Branches.h). Side branches shorter than
// `minimumLength` mm (0: twice the structure's largest inscribed radius) stay part of the branch they
// leave; a branch too small to follow, or whose parent was dropped, is left out.
bool followBranches(const BinaryVolume& volume, int64_t seed, const TskParameters& p, double minimumLength,
                    const std::function<bool(double)>& progress, TskCenterlineResult& result) {
  const std::vector<float> distance = distanceToOutside(volume);
  if (!(minimumLength > 0)) minimumLength = 2.0 * double(*std::max_element(distance.begin(), distance.end()));
  const BranchVolumes split = splitBranches(
      volume, seed, std::max(2, int(std::ceil(minimumLength / volume.spacing.minCoeff()))), &distance);
  if (!split.ok()) {
    result.error = split.error;
    return false;
  }
  std::vector<int> index(split.voxels.size(), -1);  // split branch -> output branch
  for (size_t b = 0; b < split.voxels.size(); ++b) {
    if (!progress(double(b) / double(split.voxels.size()))) {
      result.error = "aborted";
      return false;
    }
    BinaryVolume part = volume;
    std::fill(part.inside.begin(), part.inside.end(), 0);
    for (int64_t voxel : split.voxels[b]) part.inside[size_t(voxel)] = 1;
    const TubularClusters clusters = structureTube(part, split.start[b]);
    if (!clusters.ok()) continue;  // a branch too small to follow: its parent's line covers it
    Centerline line = tskAxis(part, clusters, p);
    if (line.points.size() < 2) continue;
    const int parent = split.parent[b] >= 0 ? index[size_t(split.parent[b])] : -1;
    if (split.parent[b] >= 0 && parent < 0) continue;  // its parent was dropped
    result.primitiveCenterlinePoints += int(clusters.primitive.size());
    index[b] = int(result.branches.size());
    result.branches.push_back(std::move(line));
    result.parent.push_back(parent);
  }
  return true;
}

// A branch starts at the point of its parent nearest to its own first point (the junction).
std::vector<int> junctionPoints(const std::vector<Centerline>& branches, const std::vector<int>& parents) {
  std::vector<int> junction(branches.size(), -1);
  for (size_t b = 0; b < branches.size(); ++b) {
    if (parents[b] < 0) continue;
    const Centerline& parent = branches[size_t(parents[b])];
    const Eigen::Vector3d& start = branches[b].points[0];
    size_t nearest = 0;
    for (size_t k = 1; k < parent.points.size(); ++k)
      if ((parent.points[k] - start).squaredNorm() < (parent.points[nearest] - start).squaredNorm())
        nearest = k;
    junction[b] = int(nearest);
  }
  return junction;
}

}  // namespace

BinaryVolume selectStructure(const ScalarVolume& volume, const TskCenterlineParameters& parameters,
                             int64_t& selected) {
  BinaryVolume out;
  out.size = volume.size;
  out.origin = volume.origin;
  out.spacing = volume.spacing;
  out.direction = volume.direction;
  out.inside.resize(size_t(out.voxelCount()));
  const int c = std::max(1, volume.components);
  using Type = ScalarVolume::Type;
  switch (volume.type) {
    case Type::Int8:
      selected = selectVoxels(static_cast<const int8_t*>(volume.voxels), c, parameters, out);
      break;
    case Type::UInt8:
      selected = selectVoxels(static_cast<const uint8_t*>(volume.voxels), c, parameters, out);
      break;
    case Type::Int16:
      selected = selectVoxels(static_cast<const int16_t*>(volume.voxels), c, parameters, out);
      break;
    case Type::UInt16:
      selected = selectVoxels(static_cast<const uint16_t*>(volume.voxels), c, parameters, out);
      break;
    case Type::Int32:
      selected = selectVoxels(static_cast<const int32_t*>(volume.voxels), c, parameters, out);
      break;
    case Type::UInt32:
      selected = selectVoxels(static_cast<const uint32_t*>(volume.voxels), c, parameters, out);
      break;
    case Type::Int64:
      selected = selectVoxels(static_cast<const int64_t*>(volume.voxels), c, parameters, out);
      break;
    case Type::UInt64:
      selected = selectVoxels(static_cast<const uint64_t*>(volume.voxels), c, parameters, out);
      break;
    case Type::Float32:
      selected = selectVoxels(static_cast<const float*>(volume.voxels), c, parameters, out);
      break;
    case Type::Float64:
      selected = selectVoxels(static_cast<const double*>(volume.voxels), c, parameters, out);
      break;
  }
  return out;
}

TskCenterlineResult tskCenterline(const ScalarVolume& input, const TskCenterlineParameters& parameters,
                                  const std::function<bool(double)>& progress) {
  TskCenterlineResult result;
  const auto& size = input.size;
  if (!input.voxels || size[0] < 2 || size[1] < 2 || size[2] < 2) {
    result.error = "a 3-D volume is needed (got " + std::to_string(size[0]) + " x " +
                   std::to_string(size[1]) + " x " + std::to_string(size[2]) + " voxels)";
    return result;
  }
  const auto report = [&progress](double fraction) { return !progress || progress(fraction); };

  // The structure: selection, clean-up, and the box it fills (every later step works on the box only).
  int64_t selected = 0;
  BinaryVolume volume = selectStructure(input, parameters, selected);
  if (parameters.selection == VoxelSelection::Label && selected == 0) {
    result.error = "no voxel has the label " + format(parameters.label);
    return result;
  }
  const bool dropBorder = dropsBorderParts(parameters);
  if (dropBorder) dropBorderTouchingParts(volume);
  keepLargestComponent(volume);
  if (parameters.fillHoles) fillHoles(volume);
  result.structureVoxels = int64_t(std::count(volume.inside.begin(), volume.inside.end(), 1));
  if (result.structureVoxels < 8) {
    result.error = "nothing is left to follow: " + std::to_string(result.structureVoxels) +
                   " voxels after selection and clean-up (check the label or threshold" +
                   (dropBorder ? "; parts touching the volume's border were dropped" : "") + ")";
    return result;
  }
  cropToStructure(volume, 1);
  if (!report(0.1)) {
    result.error = "aborted";
    return result;
  }

  int64_t seed = -1;
  if (parameters.seed) {
    const Eigen::Vector3d& s = *parameters.seed;
    const Eigen::Vector3d index = volume.continuousIndex(s);
    const int i = int(std::lround(index.x())), j = int(std::lround(index.y())),
              k = int(std::lround(index.z()));
    if (!volume.contains(i, j, k) || !volume.inside[size_t(volume.index(i, j, k))]) {
      result.error = "the seed (" + format(s.x()) + ", " + format(s.y()) + ", " + format(s.z()) +
                     ") mm lies outside the structure";
      return result;
    }
    seed = volume.index(i, j, k);
  }

  const bool followed =
      parameters.detectBranches
          ? followBranches(
                volume, seed, parameters.tsk, parameters.minimumBranchLength,
                [&report](double f) { return report(0.1 + 0.8 * f); }, result)
          : followTube(
                volume, seed, parameters.tsk, [&report](double f) { return report(0.1 + 0.7 * f); }, result);
  if (!followed) return result;
  if (result.branches.empty() || result.branches.front().points.size() < 2) {
    result.error = "the structure is too small for a centerline";
    return result;
  }
  result.junction = junctionPoints(result.branches, result.parent);

  if (parameters.computeSections) {
    result.sections = tubeSections(volume, result.branches.front().points, parameters.sections,
                                   [&report](double f) { return report(0.9 + 0.1 * f); });
    if (result.sections.arcLength.empty()) {
      result.error = report(1.0) ? "no section could be computed along the centerline" : "aborted";
      return result;
    }
  }
  report(1.0);
  return result;
}

}  // namespace medial
