#include "centerline/TskCenterline.h"

#include "centerline/Branches.h"
#include "centerline/StructureRuns.h"
#include "centerline/TubularClusters.h"
#include "common/Stopwatch.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <type_traits>

namespace medial {

namespace {

// The runs of the voxels `p` selects (StructureRuns.h), and how many voxels they hold.
template <class T>
std::vector<VoxelRun> runsOf(const T* values, int components, const std::array<int, 3>& size,
                             const TskCenterlineParameters& p) {
  const double label = p.label, low = p.thresholdLow, high = p.thresholdHigh;
  if constexpr (std::is_integral_v<T>) {
    // Integer voxels (CT's int16) compare as integers: the window rounded inwards, clamped to the type.
    if (p.selection == VoxelSelection::Threshold) {
      const double lo = std::max(std::ceil(low), double(std::numeric_limits<T>::lowest()));
      const double hi = std::min(std::floor(high), double(std::numeric_limits<T>::max()));
      if (!(lo <= hi)) return {};
      const T first = T(lo), last = T(hi);
      return selectedRuns(size, [&](int64_t i) {
        const T v = values[i * components];
        return v >= first && v <= last;
      });
    }
  }
  switch (p.selection) {
    case VoxelSelection::Label:
      return selectedRuns(size, [&](int64_t i) { return double(values[i * components]) == label; });
    case VoxelSelection::Threshold:
      return selectedRuns(size, [&](int64_t i) {
        const double v = double(values[i * components]);
        return v >= low && v <= high;
      });
    default:
      return selectedRuns(size, [&](int64_t i) { return values[i * components] != T(0); });
  }
}

std::vector<VoxelRun> selectedRuns(const ScalarVolume& volume, const TskCenterlineParameters& p,
                                   int64_t& selected) {
  const int c = std::max(1, volume.components);
  std::vector<VoxelRun> runs;
  using Type = ScalarVolume::Type;
  switch (volume.type) {
    case Type::Int8:
      runs = runsOf(static_cast<const int8_t*>(volume.voxels), c, volume.size, p);
      break;
    case Type::UInt8:
      runs = runsOf(static_cast<const uint8_t*>(volume.voxels), c, volume.size, p);
      break;
    case Type::Int16:
      runs = runsOf(static_cast<const int16_t*>(volume.voxels), c, volume.size, p);
      break;
    case Type::UInt16:
      runs = runsOf(static_cast<const uint16_t*>(volume.voxels), c, volume.size, p);
      break;
    case Type::Int32:
      runs = runsOf(static_cast<const int32_t*>(volume.voxels), c, volume.size, p);
      break;
    case Type::UInt32:
      runs = runsOf(static_cast<const uint32_t*>(volume.voxels), c, volume.size, p);
      break;
    case Type::Int64:
      runs = runsOf(static_cast<const int64_t*>(volume.voxels), c, volume.size, p);
      break;
    case Type::UInt64:
      runs = runsOf(static_cast<const uint64_t*>(volume.voxels), c, volume.size, p);
      break;
    case Type::Float32:
      runs = runsOf(static_cast<const float*>(volume.voxels), c, volume.size, p);
      break;
    case Type::Float64:
      runs = runsOf(static_cast<const double*>(volume.voxels), c, volume.size, p);
      break;
  }
  selected = 0;
  for (const VoxelRun& r : runs) selected += r.x1 - r.x0 + 1;
  return runs;
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
  Stopwatch stage;
  const auto lap = [&](const char* name) {
    result.stageSeconds.emplace_back(name, stage.seconds());
    stage.restart();
  };
  int64_t selected = 0;
  const std::vector<VoxelRun> runs = selectedRuns(input, parameters, selected);
  lap("selection");
  if (parameters.selection == VoxelSelection::Label && selected == 0) {
    result.error = "no voxel has the label " + format(parameters.label);
    return result;
  }
  const bool dropBorder = dropsBorderParts(parameters);
  BinaryVolume frame;
  frame.size = input.size;
  frame.origin = input.origin;
  frame.spacing = input.spacing;
  frame.direction = input.direction;
  ChosenPart part = largestPart(frame, runs, dropBorder, 1);
  BinaryVolume volume = std::move(part.volume);
  if (parameters.fillHoles && part.voxels > 0) part.voxels += fillHoles(volume);
  result.structureVoxels = part.voxels;
  lap("cleanup");
  if (result.structureVoxels < 8) {
    result.error = "nothing is left to follow: " + std::to_string(result.structureVoxels) +
                   " voxels after selection and clean-up (check the label or threshold" +
                   (dropBorder ? "; parts touching the volume's border were dropped" : "") + ")";
    return result;
  }
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
  lap("axis");
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
    lap("sections");
  }
  report(1.0);
  return result;
}

}  // namespace medial
