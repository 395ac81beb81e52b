#include "centerline/TskCenterline.h"

#include "centerline/Branches.h"
#include "centerline/GapBridges.h"
#include "centerline/Junctions.h"
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

// Calls f(values) with the volume's voxels as their C++ type.
template <class F>
void withVoxels(const ScalarVolume& volume, F&& f) {
  using Type = ScalarVolume::Type;
  switch (volume.type) {
    case Type::Int8:
      return f(static_cast<const int8_t*>(volume.voxels));
    case Type::UInt8:
      return f(static_cast<const uint8_t*>(volume.voxels));
    case Type::Int16:
      return f(static_cast<const int16_t*>(volume.voxels));
    case Type::UInt16:
      return f(static_cast<const uint16_t*>(volume.voxels));
    case Type::Int32:
      return f(static_cast<const int32_t*>(volume.voxels));
    case Type::UInt32:
      return f(static_cast<const uint32_t*>(volume.voxels));
    case Type::Int64:
      return f(static_cast<const int64_t*>(volume.voxels));
    case Type::UInt64:
      return f(static_cast<const uint64_t*>(volume.voxels));
    case Type::Float32:
      return f(static_cast<const float*>(volume.voxels));
    case Type::Float64:
      return f(static_cast<const double*>(volume.voxels));
  }
}

std::string format(double value);  // a number as short as it prints (below)

// VoxelSelection::Automatic made concrete for `volume` (TskCenterline.h), from a regular sample of its
// voxels (about two million: a CT has millions of air voxels); false with `error` set when the volume
// holds no structure to follow without a label or a window.
bool resolveSelection(const ScalarVolume& volume, TskCenterlineParameters& p, std::vector<std::string>& notes,
                      Error& error) {
  if (p.selection != VoxelSelection::Automatic) return true;
  const int64_t count = int64_t(volume.size[0]) * volume.size[1] * volume.size[2];
  const int64_t stride = std::max<int64_t>(1, count / 2000000);
  const int c = std::max(1, volume.components);
  double lowest = std::numeric_limits<double>::infinity();
  int64_t samples = 0, nonZero = 0, inWindow = 0;
  bool signedValues = false;
  withVoxels(volume, [&](const auto* values) {
    using T = std::remove_cv_t<std::remove_pointer_t<decltype(values)>>;
    signedValues = std::is_signed_v<T>;
    for (int64_t i = 0; i < count; i += stride, ++samples) {
      const double v = double(values[i * c]);
      lowest = std::min(lowest, v);
      nonZero += v != 0;
      inWindow += v >= p.thresholdLow && v <= p.thresholdHigh;
    }
  });
  const std::string window = format(p.thresholdLow) + " to " + format(p.thresholdHigh);
  if (signedValues && lowest < -200) {  // Hounsfield units: air is -1000, water 0
    if (inWindow == 0) {
      error = "the volume looks like a CT in Hounsfield units (values down to " + format(lowest) +
              ") but has no voxel in the air window (" + window +
              "): choose a threshold window (--threshold LO:HI) or a label (--label L)";
      return false;
    }
    // Everything below the window's top: air voxels of a noisy CT stored without clipping reach below
    // -1024 HU, and leaving them out put holes in the lumen (the ct-spiral phantom's line 1.8 mm off).
    p.selection = VoxelSelection::Threshold;
    p.thresholdLow = -std::numeric_limits<double>::infinity();
    notes.push_back("the volume looks like a CT in Hounsfield units: the structure is its air (at most " +
                    format(p.thresholdHigh) +
                    " HU, parts touching the border dropped); --threshold or --label choose another");
    return true;
  }
  if (2 * nonZero > samples) {
    error = "the non-zero voxels fill " +
            std::to_string(int(std::lround(100.0 * double(nonZero) / double(samples)))) +
            " % of the volume: that is no tube to follow; choose a threshold window (--threshold LO:HI) or a "
            "label (--label L)";
    return false;
  }
  p.selection = VoxelSelection::NonZero;
  return true;
}

std::vector<VoxelRun> selectedRuns(const ScalarVolume& volume, const TskCenterlineParameters& p,
                                   int64_t& selected) {
  const int c = std::max(1, volume.components);
  std::vector<VoxelRun> runs;
  withVoxels(volume, [&](const auto* values) { runs = runsOf(values, c, volume.size, p); });
  selected = 0;
  for (const VoxelRun& r : runs) selected += r.x1 - r.x0 + 1;
  return runs;
}

// The cost per mm of a bridge through the voxels of box lo..hi (GapBridges.h): 1 in the selection, and
// for a threshold window growing by 1 per 250 above it (fat 3, soft tissue 3.6, contrast or bone 5 at
// most with the colon-air window), so that a bridge keeps to low densities; 2 outside a label.
CostBox costBox(const ScalarVolume& volume, const TskCenterlineParameters& p, const std::array<int, 3>& lo,
                const std::array<int, 3>& hi) {
  CostBox box;
  box.first = lo;
  for (size_t a = 0; a < 3; ++a) box.size[a] = hi[a] - lo[a] + 1;
  box.cost.resize(size_t(box.size[0]) * box.size[1] * box.size[2]);
  const int c = std::max(1, volume.components);
  withVoxels(volume, [&](const auto* values) {
    size_t out = 0;
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) {
          const double v =
              double(values[c * (x + int64_t(volume.size[0]) * (y + int64_t(volume.size[1]) * z))]);
          float cost = 1;
          if (p.selection == VoxelSelection::Threshold)
            cost = v <= p.thresholdHigh ? 1.0f : float(1.0 + std::min(v - p.thresholdHigh, 1000.0) / 250.0);
          else if (p.selection == VoxelSelection::Label)
            cost = v == p.label ? 1.0f : 2.0f;
          else
            cost = v != 0 ? 1.0f : 2.0f;
          box.cost[out++] = cost;
        }
  });
  return box;
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

// The paper's intermediate results of one tube (recordStages).
void keepStages(const BinaryVolume& volume, const TubularClusters& clusters, TskStages& stages) {
  std::vector<int> layerOf;
  manhattanLayers(volume, clusters.primitive.front(), layerOf);
  for (size_t k = 0; k < clusters.orderedVoxels.size(); ++k) {
    const int64_t voxel = clusters.orderedVoxels[k];
    stages.voxels.push_back(volume.physical(voxel));
    stages.layer.push_back(layerOf[size_t(voxel)]);
    stages.cluster.push_back(clusters.orderedCluster[k]);
  }
  for (int64_t voxel : clusters.primitive) stages.primitive.push_back(volume.physical(voxel));
  stages.boxSize = volume.size;
  stages.boxOrigin = volume.origin;
  stages.boxSpacing = volume.spacing;
  stages.boxDirection = volume.direction;
  stages.layerVolume = layerOf;
  stages.clusterVolume.assign(layerOf.size(), -1);
  for (size_t k = 0; k < clusters.orderedVoxels.size(); ++k)
    stages.clusterVolume[size_t(clusters.orderedVoxels[k])] = clusters.orderedCluster[k];
  stages.primitiveLayer = clusters.primitiveLayer;
  stages.primitiveBorderDistance = clusters.primitiveBorderDistance;
}

// Phase I and II along one tube (the paper).
bool followTube(const BinaryVolume& volume, int64_t seed, const TskParameters& p, bool recordStages,
                const std::function<bool(double)>& progress, TskCenterlineResult& result) {
  const TubularClusters clusters = structureTube(volume, seed, progress);
  if (!clusters.ok()) {
    result.error = clusters.error;
    return false;
  }
  result.primitiveCenterlinePoints = int(clusters.primitive.size());
  if (recordStages) keepStages(volume, clusters, result.stages);
  result.branches = {tskAxis(volume, clusters, p, recordStages ? &result.stages.model : nullptr)};
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
      result.error = Error::cancelled();
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

double polylineLength(const Eigen::Vector3d& from, const std::vector<Eigen::Vector3d>& inner,
                      const Eigen::Vector3d& to) {
  double length = 0;
  Eigen::Vector3d at = from;
  for (const Eigen::Vector3d& p : inner) length += (p - at).norm(), at = p;
  return std::max(length + (to - at).norm(), 1e-9);
}

// A bridge across a gap (GapBridges.h): the least-cost path through the volume in the box around the two
// ends grown by half their distance (at least 5 mm), smoothed and resampled at `spacing`; or, when it costs
// at most a quarter more, the Hermite curve continuing both ends' directions (in a collapsed segment the CT
// holds nothing that marks the tube's course, and the least-cost path cuts the bend as a chord, 3 voxels off
// a helix's axis). Its gap is the length of the bridge outside the selection (cost above 1).
Bridge bridgeThroughVolume(const ScalarVolume& input, const TskCenterlineParameters& p,
                           const BinaryVolume& frame, const BridgeEnds& ends, double spacing) {
  auto voxelOf = [&](const Eigen::Vector3d& point) {
    const Eigen::Vector3d c = frame.continuousIndex(point);
    std::array<int, 3> v{};
    for (int a = 0; a < 3; ++a)
      v[size_t(a)] = std::clamp(int(std::lround(c[a])), 0, frame.size[size_t(a)] - 1);
    return v;
  };
  const Eigen::Vector3d &from = ends.from, &to = ends.to;
  const std::array<int, 3> a = voxelOf(from), b = voxelOf(to);
  const double margin = std::max(5.0, 0.5 * (to - from).norm());
  std::array<int, 3> lo{}, hi{};
  for (size_t k = 0; k < 3; ++k) {
    const int grow = int(std::ceil(margin / frame.spacing[int(k)]));
    lo[k] = std::max(0, std::min(a[k], b[k]) - grow);
    hi[k] = std::min(frame.size[k] - 1, std::max(a[k], b[k]) + grow);
  }
  const CostBox box = costBox(input, p, lo, hi);
  const std::vector<std::array<int, 3>> path = leastCostPath(box, frame.spacing, a, b);
  Bridge bridge;
  if (path.empty()) return bridge;
  // The cost per mm at a point (the box's voxel nearest it; 5, the most, outside the box).
  const auto costAt = [&](const Eigen::Vector3d& point) {
    const std::array<int, 3> v = voxelOf(point);
    for (size_t k = 0; k < 3; ++k)
      if (v[k] < lo[k] || v[k] > hi[k]) return 5.0;
    return double(box.cost[size_t(
        (v[0] - lo[0]) + int64_t(box.size[0]) * ((v[1] - lo[1]) + int64_t(box.size[1]) * (v[2] - lo[2])))]);
  };
  // A bridge's total cost and its length outside the selection, segment by segment at the midpoints.
  const auto measure = [&](const std::vector<Eigen::Vector3d>& inner, double& outside) {
    std::vector<Eigen::Vector3d> all{from};
    all.insert(all.end(), inner.begin(), inner.end());
    all.push_back(to);
    double cost = 0;
    outside = 0;
    for (size_t k = 1; k < all.size(); ++k) {
      const double length = (all[k] - all[k - 1]).norm(), c = costAt(0.5 * (all[k] + all[k - 1]));
      cost += length * c;
      if (c > 1.0) outside += length;
    }
    return cost;
  };
  std::vector<Eigen::Vector3d> points;
  for (const auto& v : path) points.push_back(frame.physical(Eigen::Vector3d(v[0], v[1], v[2])));
  std::vector<Eigen::Vector3d> leastCost = bridgePoints(from, to, points, spacing);
  std::vector<Eigen::Vector3d> curve =
      hermiteCurve(from, ends.fromDirection, to, ends.toDirection, spacing, kBridgeTangentScale);
  double leastCostGap = 0, curveGap = 0;
  const double leastCostCost = measure(leastCost, leastCostGap), curveCost = measure(curve, curveGap);
  // Per mm: a longer curve through the same tissue costs no more (a quarter more: denser tissue, bone).
  const double curveLength = polylineLength(from, curve, to),
               leastCostLength = polylineLength(from, leastCost, to);
  const bool smooth = curveCost / curveLength <= 1.25 * leastCostCost / leastCostLength;

  bridge.points = smooth ? std::move(curve) : std::move(leastCost);
  bridge.gap = smooth ? curveGap : leastCostGap;
  return bridge;
}

// Every part in `kept` followed in its own box (phases I and II) and the parts chained across their gaps
// (GapBridges.h): one polyline per chain. `seed`: a voxel of the whole volume, or -1.
bool followParts(const ScalarVolume& input, const TskCenterlineParameters& p, const BinaryVolume& frame,
                 const std::vector<VoxelRun>& runs, const StructureParts& parts, const std::vector<int>& kept,
                 const std::array<int, 3>* seed, const std::function<bool(double)>& progress,
                 TskCenterlineResult& result) {
  int64_t total = 0, done = 0;
  for (int k : kept) total += parts.parts[size_t(k)].voxels;
  const int seedPart = seed ? parts.partAt(runs, (*seed)[0], (*seed)[1], (*seed)[2]) : -1;
  std::vector<Centerline> lines;
  int startLine = -1;
  int tooSmall = 0;
  for (int k : kept) {
    std::array<int, 3> first{};
    BinaryVolume box = partsInBox(frame, runs, parts, {k}, 1, &first);
    if (p.fillHoles) fillHoles(box);
    const int64_t localSeed =
        k == seedPart ? box.index((*seed)[0] - first[0], (*seed)[1] - first[1], (*seed)[2] - first[2]) : -1;
    const int64_t voxels = parts.parts[size_t(k)].voxels;
    TskCenterlineResult one;
    const bool record = p.recordStages && result.stages.voxels.empty();  // the first part followed
    const bool followed = followTube(
        box, localSeed, p.tsk, record,
        [&](double f) { return progress((double(done) + f * double(voxels)) / double(total)); }, one);
    if (followed && record) result.stages = std::move(one.stages);
    done += voxels;
    if (!followed && one.error.isCancelled()) {
      result.error = one.error;
      return false;
    }
    if (!followed || one.branches.front().points.size() < 2) {
      if (k == seedPart) {
        result.error = "the part of the structure holding the seed is too small for a centerline";
        return false;
      }
      ++tooSmall;
      continue;
    }
    if (k == seedPart) startLine = int(lines.size());
    result.primitiveCenterlinePoints += one.primitiveCenterlinePoints;
    lines.push_back(std::move(one.branches.front()));
  }
  if (lines.empty()) return false;
  result.partsFollowed = int(lines.size());
  if (tooSmall > 0)
    result.notes.push_back(std::to_string(tooSmall) + " part(s) too small for a centerline were left out");

  const double spacing = p.tsk.sampleSpacing > 0 ? p.tsk.sampleSpacing : frame.spacing.minCoeff();
  const PartChains chains = chainParts(lines, startLine, p.maxGap, [&](const BridgeEnds& ends) {
    return bridgeThroughVolume(input, p, frame, ends, spacing);
  });
  for (const auto& chain : chains.chains) {
    for (size_t k = 1; k < chain.size(); ++k) result.bridgedGaps.push_back(chain[k].bridge.gap);
    result.branches.push_back(joinChain(lines, chain));
    result.parent.push_back(-1);
  }
  if (!result.bridgedGaps.empty()) {
    std::ostringstream note;
    note << lines.size() << " parts of the structure joined across " << result.bridgedGaps.size()
         << " gap(s) of";
    for (double gap : result.bridgedGaps) note << ' ' << std::lround(gap);
    note << " mm (point data Bridged = 1 there)";
    result.notes.push_back(note.str());
  }
  for (double gap : chains.brokenGaps)
    result.notes.push_back("a gap of " + std::to_string(std::lround(gap)) +
                           " mm is longer than the maximum gap (" + format(p.maxGap) +
                           " mm): the centerline is split there into another polyline");
  return true;
}

// Sections that lie on a bridge have no lumen: they are marked and their walls and measures set to NaN.
void markBridgedSections(const Centerline& line, TubeSections& sections) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  sections.bridged.assign(sections.arcLength.size(), 0);
  if (line.bridged.empty()) return;
  size_t k = 0;
  for (size_t s = 0; s < sections.arcLength.size(); ++s) {
    while (k + 1 < line.arcLength.size() && line.arcLength[k + 1] < sections.arcLength[s]) ++k;
    const size_t nearest = k + 1 < line.arcLength.size() && line.arcLength[k + 1] - sections.arcLength[s] <
                                                                sections.arcLength[s] - line.arcLength[k]
                               ? k + 1
                               : k;
    if (!line.bridged[nearest]) continue;
    sections.bridged[s] = 1;
    std::fill(sections.wall[s].begin(), sections.wall[s].end(), nan);
    sections.minDiameter[s] = sections.maxDiameter[s] = sections.perimeter[s] = sections.area[s] = nan;
  }
}

// The parts kept: the largest one left after the border rule, and with gaps bridged every other one of
// at least the minimum volume (at most kMostParts, the largest); a note says how many were left out.
std::vector<int> keptParts(const StructureParts& parts, const TskCenterlineParameters& parameters,
                           bool dropBorder, double voxelVolume, std::vector<std::string>& notes) {
  std::vector<int> kept;
  const bool bridging = !parameters.detectBranches && parameters.maxGap > 0;
  int smaller = 0;
  for (size_t k = 0; k < parts.parts.size(); ++k) {
    const StructureParts::Part& part = parts.parts[k];
    if (dropBorder && part.border) continue;
    if (kept.empty() || (bridging && double(part.voxels) * voxelVolume >= parameters.minimumPartVolume))
      kept.push_back(int(k));
    else if (bridging)
      ++smaller;
  }
  constexpr size_t kMostParts = 64;  // the largest; more would be noise, not a colon's segments
  if (kept.size() > kMostParts) {
    smaller += int(kept.size() - kMostParts);
    kept.resize(kMostParts);
  }
  if (smaller > 0 && kept.size() > 1)
    notes.push_back(std::to_string(smaller) + " smaller part(s) of the structure were left out (under " +
                    format(parameters.minimumPartVolume) + " mm^3, or beyond the " +
                    std::to_string(kMostParts) + " largest)");
  return kept;
}

// The given seed as a voxel of the structure's box (`seed`) and of the whole volume (`seedVoxel`); false
// with `error` set when it lies outside the structure.
bool placeSeed(const Eigen::Vector3d& s, const BinaryVolume& volume, const BinaryVolume& frame, int64_t& seed,
               std::array<int, 3>& seedVoxel, Error& error) {
  const Eigen::Vector3d index = volume.continuousIndex(s);
  const int i = int(std::lround(index.x())), j = int(std::lround(index.y())), k = int(std::lround(index.z()));
  if (!volume.contains(i, j, k) || !volume.inside[size_t(volume.index(i, j, k))]) {
    error = "the seed (" + format(s.x()) + ", " + format(s.y()) + ", " + format(s.z()) +
            ") mm lies outside the structure";
    return false;
  }
  seed = volume.index(i, j, k);
  const Eigen::Vector3d whole = frame.continuousIndex(s);
  seedVoxel = {int(std::lround(whole.x())), int(std::lround(whole.y())), int(std::lround(whole.z()))};
  return true;
}

}  // namespace

TskCenterlineResult tskCenterline(const ScalarVolume& input, const TskCenterlineParameters& given,
                                  const std::function<bool(double)>& progress) {
  TskCenterlineResult result;
  const auto& size = input.size;
  if (!input.voxels || size[0] < 2 || size[1] < 2 || size[2] < 2) {
    result.error = "a 3-D volume is needed (got " + std::to_string(size[0]) + " x " +
                   std::to_string(size[1]) + " x " + std::to_string(size[2]) + " voxels)";
    return result;
  }
  TskCenterlineParameters parameters = given;
  if (!resolveSelection(input, parameters, result.notes, result.error)) return result;
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
  const StructureParts parts = labelParts(size, runs);
  const std::vector<int> kept = keptParts(parts, parameters, dropBorder, frame.spacing.prod(), result.notes);
  BinaryVolume volume = partsInBox(frame, runs, parts, kept, 1);
  result.structureVoxels = 0;
  for (int k : kept) result.structureVoxels += parts.parts[size_t(k)].voxels;
  if (parameters.fillHoles && !kept.empty()) result.structureVoxels += fillHoles(volume);
  lap("cleanup");
  if (result.structureVoxels < 8) {
    result.error = "nothing is left to follow: " + std::to_string(result.structureVoxels) +
                   " voxels after selection and clean-up (check the label or threshold" +
                   (dropBorder ? "; parts touching the volume's border were dropped" : "") + ")";
    return result;
  }
  if (!report(0.1)) {
    result.error = Error::cancelled();
    return result;
  }

  int64_t seed = -1;
  std::array<int, 3> seedVoxel{};
  if (parameters.seed && !placeSeed(*parameters.seed, volume, frame, seed, seedVoxel, result.error))
    return result;

  bool followed = false;
  if (parameters.detectBranches)
    followed = followBranches(
        volume, seed, parameters.tsk, parameters.minimumBranchLength,
        [&report](double f) { return report(0.1 + 0.8 * f); }, result);
  else if (kept.size() == 1)
    followed = followTube(
        volume, seed, parameters.tsk, parameters.recordStages,
        [&report](double f) { return report(0.1 + 0.7 * f); }, result);
  else
    followed = followParts(
        input, parameters, frame, runs, parts, kept, parameters.seed ? &seedVoxel : nullptr,
        [&report](double f) { return report(0.1 + 0.7 * f); }, result);
  if (followed && result.partsFollowed == 0) result.partsFollowed = 1;
  lap("axis");
  if (!followed) {
    if (result.error.empty()) result.error = "the structure is too small for a centerline";
    return result;
  }
  if (result.branches.empty() || result.branches.front().points.size() < 2) {
    result.error = "the structure is too small for a centerline";
    return result;
  }
  if (parameters.detectBranches) placeJunctions(volume, result.branches, result.parent);
  result.junction = junctionPoints(result.branches, result.parent);
  if (result.partsFollowed > 1)
    for (Centerline& line : result.branches) refineBridges(volume, line);

  if (parameters.computeSections) {
    result.sections = tubeSections(volume, result.branches.front().points, parameters.sections,
                                   [&report](double f) { return report(0.9 + 0.1 * f); });
    if (result.sections.arcLength.empty()) {
      result.error =
          report(1.0) ? Error("no section could be computed along the centerline") : Error::cancelled();
      return result;
    }
    markBridgedSections(result.branches.front(), result.sections);
    lap("sections");
  }
  if (parameters.keepStructure) result.structure = std::move(volume);
  report(1.0);
  return result;
}

}  // namespace medial
