#include "centerline/TubularClusters.h"

#include <algorithm>
#include <cstring>
#include <cmath>
#include <functional>
#include <limits>
#include <thread>

namespace medial {

// Step 2b, computed only for the voxels that are compared (the last layer of each section in step 3,
// the voxels around the axis for its radius): a pass over the whole box costs a large part of a
// full-size CT's run.
float sixDirectionBorderDistance(const BinaryVolume& v, int64_t voxel) {
  const auto c = v.coordinates(voxel);
  const int64_t strides[3] = {1, v.size[0], int64_t(v.size[0]) * v.size[1]};
  float best = std::numeric_limits<float>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const int p = c[size_t(axis)], length = v.size[size_t(axis)];
    const int64_t stride = strides[axis];
    int before = p, after = p;  // the run of inside voxels through p
    while (before > 0 && v.inside[size_t(voxel - (p - before + 1) * stride)]) --before;
    while (after < length - 1 && v.inside[size_t(voxel + (after + 1 - p) * stride)]) ++after;
    const double step = v.spacing[axis];
    best = std::min(best, float((p - (before - 1)) * step));
    best = std::min(best, float((after + 1 - p) * step));
  }
  return best;
}

namespace {

// Whether no voxel of the structure lies on the volume's faces: then every neighbour of a structure voxel
// is inside the volume, one index offset away.
bool keepsOffFaces(const BinaryVolume& v) {
  const int nx = v.size[0], ny = v.size[1], nz = v.size[2];
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; i += (k == 0 || k == nz - 1 || j == 0 || j == ny - 1) ? 1 : std::max(1, nx - 1))
        if (v.inside[size_t(v.index(i, j, k))]) return false;
  return true;
}

}  // namespace

std::vector<std::vector<int64_t>> manhattanLayers(const BinaryVolume& v, int64_t seed,
                                                  std::vector<int>& layer) {
  layer.assign(size_t(v.voxelCount()), -1);
  std::vector<std::vector<int64_t>> layers;
  if (seed < 0 || seed >= v.voxelCount()) return layers;
  // Layer by layer from frontier to frontier. Where the structure keeps off the volume's faces (a box
  // cropped with a margin: the usual case), a neighbour is an index offset, with no bounds to check.
  const int nx = v.size[0], ny = v.size[1];
  const bool offFaces = keepsOffFaces(v);
  const int64_t offsets[6] = {1, -1, nx, -int64_t(nx), int64_t(nx) * ny, -int64_t(nx) * ny};
  static const int steps[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  layer[size_t(seed)] = 0;
  layers.push_back({seed});
  for (int l = 0; !layers[size_t(l)].empty(); ++l) {
    std::vector<int64_t> next;
    for (int64_t at : layers[size_t(l)]) {
      if (offFaces) {
        for (int64_t offset : offsets) {
          const int64_t n = at + offset;
          if (v.inside[size_t(n)] && layer[size_t(n)] < 0) {
            layer[size_t(n)] = l + 1;
            next.push_back(n);
          }
        }
        continue;
      }
      const auto c = v.coordinates(at);
      for (const auto& s : steps) {
        const int i = c[0] + s[0], j = c[1] + s[1], k = c[2] + s[2];
        if (!v.contains(i, j, k)) continue;
        const int64_t n = v.index(i, j, k);
        if (v.inside[size_t(n)] && layer[size_t(n)] < 0) {
          layer[size_t(n)] = l + 1;
          next.push_back(n);
        }
      }
    }
    layers.push_back(std::move(next));
  }
  layers.pop_back();  // the empty frontier
  return layers;
}

namespace {

std::vector<std::vector<int64_t>> growLayers(const BinaryVolume& v, int64_t seed, std::vector<int>& layer) {
  return manhattanLayers(v, seed, layer);
}

// The lowest voxel of the last layer: an end of the structure as seen from `from`.
// Breadth-first (6-connected) with frontiers only and a byte per voxel: no layer numbers kept.
int64_t farEnd(const BinaryVolume& v, int64_t from, int& distance) {
  std::vector<uint8_t> seen(v.inside.size(), 0);
  std::vector<int64_t> frontier{from}, next;
  seen[size_t(from)] = 1;
  distance = 0;
  static const int steps[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const bool offFaces = keepsOffFaces(v);
  const int64_t offsets[6] = {
      1, -1, v.size[0], -int64_t(v.size[0]), int64_t(v.size[0]) * v.size[1], -int64_t(v.size[0]) * v.size[1]};
  auto reach = [&](int64_t n) {
    if (v.inside[size_t(n)] && !seen[size_t(n)]) {
      seen[size_t(n)] = 1;
      next.push_back(n);
    }
  };
  while (true) {
    next.clear();
    for (int64_t at : frontier) {
      if (offFaces) {
        for (int64_t offset : offsets) reach(at + offset);
        continue;
      }
      const auto c = v.coordinates(at);
      for (const auto& s : steps)
        if (v.contains(c[0] + s[0], c[1] + s[1], c[2] + s[2]))
          reach(v.index(c[0] + s[0], c[1] + s[1], c[2] + s[2]));
    }
    if (next.empty()) break;
    frontier.swap(next);
    ++distance;
  }
  return *std::min_element(frontier.begin(), frontier.end(),
                           [&](int64_t a, int64_t b) { return v.physical(a).z() < v.physical(b).z(); });
}

}  // namespace

int64_t lowestVoxel(const BinaryVolume& v) {
  // Physical z is linear in the index: z = z0 + a i + b j + c k. With a = b = 0 (axial slices, the usual
  // case) every voxel of a slice has the same z, so the lowest slice holding a voxel holds the answer.
  const Eigen::RowVector3d zRow = v.direction.row(2).cwiseProduct(v.spacing.transpose());
  const double a = zRow[0], b = zRow[1], c = zRow[2];
  const int64_t sliceSize = int64_t(v.size[0]) * v.size[1];
  if (a == 0 && b == 0) {
    for (int step = 0; step < v.size[2]; ++step) {
      const int k = c >= 0 ? step : v.size[2] - 1 - step;
      const auto begin = v.inside.begin() + long(k * sliceSize);
      const auto found = std::find(begin, begin + long(sliceSize), uint8_t(1));
      if (found != begin + long(sliceSize)) return k * sliceSize + (found - begin);
    }
    return -1;
  }
  int64_t best = -1;
  double bestZ = INFINITY;
  int64_t i = 0;
  for (int k = 0; k < v.size[2]; ++k)
    for (int y = 0; y < v.size[1]; ++y)
      for (int x = 0; x < v.size[0]; ++x, ++i)
        if (v.inside[size_t(i)]) {
          const double z = a * x + b * y + c * k;
          if (z < bestZ - 1e-9) {
            bestZ = z;
            best = i;
          }
        }
  return best;
}

namespace {

// Step 1, beyond the paper: the lowest voxel starts a colon (the rectum), but not a U standing on its
// bend. When it is no end of the structure (an end F found from it is farther from the other end G than
// it is), the lower of the two ends is taken instead.
int64_t structureEnd(const BinaryVolume& v, int64_t lowest) {
  int fromSeed = 0, acrossEnds = 0;
  const int64_t f = farEnd(v, lowest, fromSeed);
  const int64_t g = farEnd(v, f, acrossEnds);
  if (double(fromSeed) < 0.9 * double(acrossEnds)) return v.physical(f).z() <= v.physical(g).z() ? f : g;
  return lowest;
}

// Step 3: the primitive centerline, section by section: each section ends at the layer where its height
// cubed passes 4 / pi times its volume (eq. 1), and its point is the voxel of that layer farthest from the
// border.
void choosePrimitivePoints(const BinaryVolume& v, int64_t seed,
                           const std::vector<std::vector<int64_t>>& layers, TubularClusters& r) {
  r.primitive.push_back(seed);
  r.primitiveLayer.push_back(0);
  r.primitiveBorderDistance.push_back(sixDirectionBorderDistance(v, seed));
  int current = 0;
  while (current + 1 < int(layers.size())) {
    int64_t volume = 1;
    int height = 0, last = current;
    for (int l = current + 1; l < int(layers.size()); ++l) {
      volume += int64_t(layers[size_t(l)].size());
      ++height;
      last = l;
      if (double(height) * height * height > 4.0 * double(volume) / M_PI) break;  // eq. (1)
    }
    const auto& lastLayer = layers[size_t(last)];
    int64_t chosen = lastLayer.front();
    float chosenDistance = -1;
    for (int64_t voxel : lastLayer)  // the first of the farthest from the border, as max_element takes
      if (const float d = sixDirectionBorderDistance(v, voxel); d > chosenDistance) {
        chosenDistance = d;
        chosen = voxel;
      }
    r.primitive.push_back(chosen);
    r.primitiveBorderDistance.push_back(chosenDistance);
    r.primitiveLayer.push_back(last);
    current = last;
  }
}

// Dm_j of step 4: each primitive point's distance to its nearest reached neighbour voxel.
std::vector<double> nearestNeighbourDistances(const BinaryVolume& v,
                                              const std::vector<Eigen::Vector3d>& vertex,
                                              const std::vector<int64_t>& primitive,
                                              const std::vector<int>& layer) {
  std::vector<double> nearest(primitive.size(), v.spacing.minCoeff());
  for (size_t j = 0; j < primitive.size(); ++j) {
    const auto c = v.coordinates(primitive[j]);
    double best = INFINITY;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          if ((dx | dy | dz) == 0 || !v.contains(c[0] + dx, c[1] + dy, c[2] + dz)) continue;
          const int64_t other = v.index(c[0] + dx, c[1] + dy, c[2] + dz);
          if (layer[size_t(other)] >= 0) best = std::min(best, (v.physical(other) - vertex[j]).norm());
        }
    if (std::isfinite(best)) nearest[j] = best;
  }
  return nearest;
}

struct Member {  // 16 bytes: a full-size colon has millions
  int64_t voxel;
  float relative;
  int cluster;
};

// Step 4: clusters by membership mu_ij = Dm_j / D_ij among the vertices around the voxel's section. Frees
// `layer` and `layers` as soon as they are used (hundreds of MB on a full-size CT).
std::vector<Member> clusterMembers(const BinaryVolume& v, std::vector<std::vector<int64_t>>& layers,
                                   std::vector<int>& layer, int64_t reached, const TubularClusters& r) {
  const int n = int(r.primitive.size());
  std::vector<Eigen::Vector3d> vertex(static_cast<size_t>(n));
  for (int j = 0; j < n; ++j) vertex[size_t(j)] = v.physical(r.primitive[size_t(j)]);
  const std::vector<double> nearest = nearestNeighbourDistances(v, vertex, r.primitive, layer);  // Dm_j
  std::vector<int>().swap(layer);
  // Each voxel's cluster and position in it, layer by layer; two threads take half of the layers each
  // (by voxel count) and their lists are joined in layer order.
  const auto assign = [&](int fromLayer, int toLayer, std::vector<Member>& out) {
    for (int l = fromLayer; l < toLayer; ++l) {
      const int after = int(std::lower_bound(r.primitiveLayer.begin(), r.primitiveLayer.end(), l) -
                            r.primitiveLayer.begin());
      const int first = std::max(0, after - 2), lastCandidate = std::min(n - 1, after + 1);
      for (int64_t voxel : layers[size_t(l)]) {
        const Eigen::Vector3d p = v.physical(voxel);
        auto membership = [&](int j) {
          if (j < 0 || j >= n) return 0.0;
          const double d = (p - vertex[size_t(j)]).norm();
          return d > 0 ? nearest[size_t(j)] / d : std::numeric_limits<double>::infinity();
        };
        int cluster = first;
        double best = -1;
        for (int j = first; j <= lastCandidate; ++j)
          if (const double mu = membership(j); mu > best) {
            best = mu;
            cluster = j;
          }
        const double next = membership(cluster + 1), previous = membership(cluster - 1);
        out.push_back({voxel, std::isfinite(best) ? float(next - previous) : 0.0f, cluster});
      }
    }
  };
  int middle = 0;
  for (int64_t counted = 0; middle < int(layers.size()) && 2 * counted < reached; ++middle)
    counted += int64_t(layers[size_t(middle)].size());
  std::vector<Member> members, later;
  members.reserve(size_t(reached));
  std::thread second(assign, middle, int(layers.size()), std::ref(later));
  assign(0, middle, members);
  second.join();
  members.insert(members.end(), later.begin(), later.end());
  std::vector<Member>().swap(later);  // the lists and layers go before step 5 copies the members
  std::vector<std::vector<int64_t>>().swap(layers);
  return members;
}

// Step 5: the total order: by cluster (a counting sort), then by relative position within each, stable
// (ties keep the layer order): each cluster sorts 64-bit keys, the position's float bits made
// order-preserving above the member's rank in the cluster. Frees `members`.
void orderVoxels(std::vector<Member>& members, int n, TubularClusters& r) {
  std::vector<size_t> start(size_t(n) + 1, 0);
  for (const Member& m : members) ++start[size_t(m.cluster) + 1];
  for (int j = 0; j < n; ++j) start[size_t(j) + 1] += start[size_t(j)];
  std::vector<uint64_t> keys(members.size());
  std::vector<int64_t> voxelAt(members.size());  // the voxels of each cluster, in layer order
  std::vector<size_t> at(start.begin(), start.end() - 1);
  for (const Member& m : members) {
    const size_t slot = at[size_t(m.cluster)]++;
    uint32_t bits;
    std::memcpy(&bits, &m.relative, sizeof bits);
    bits = (bits & 0x80000000u) ? ~bits : (bits | 0x80000000u);  // float order as unsigned order
    keys[slot] = (uint64_t(bits) << 32) | uint64_t(slot - start[size_t(m.cluster)]);
    voxelAt[slot] = m.voxel;
  }
  const size_t count = members.size();
  std::vector<Member>().swap(members);
  const auto sortClusters = [&](int from, int to) {
    for (int j = from; j < to; ++j)
      std::sort(keys.begin() + long(start[size_t(j)]), keys.begin() + long(start[size_t(j) + 1]));
  };
  std::thread secondHalf(sortClusters, n / 2, n);
  sortClusters(0, n / 2);
  secondHalf.join();
  r.orderedVoxels.resize(count);
  r.orderedCluster.resize(count);
  for (int j = 0; j < n; ++j)
    for (size_t k = start[size_t(j)]; k < start[size_t(j) + 1]; ++k) {
      r.orderedVoxels[k] = voxelAt[start[size_t(j)] + size_t(keys[k] & 0xffffffffu)];
      r.orderedCluster[k] = j;
    }
}

}  // namespace

TubularClusters structureTube(const BinaryVolume& v, int64_t seed,
                              const std::function<bool(double)>& progress) {
  TubularClusters r;
  auto aborted = [&](double f) {
    if (progress && !progress(f)) {
      r.error = Error::cancelled();
      return true;
    }
    return false;
  };
  const bool autoSeed = seed < 0;
  if (autoSeed) seed = lowestVoxel(v);
  if (seed < 0) {
    r.error = "the structure is empty (no voxel selected)";
    return r;
  }
  if (seed >= v.voxelCount() || !v.inside[size_t(seed)]) {
    r.error = "the seed lies outside the structure";
    return r;
  }
  if (autoSeed) seed = structureEnd(v, seed);  // step 1

  // Step 2a: Manhattan layers grown inside the structure.
  std::vector<int> layer;  // per voxel, freed once step 4 has used it
  std::vector<std::vector<int64_t>> layers = growLayers(v, seed, layer);
  int64_t reached = 0;
  for (const auto& l : layers) reached += int64_t(l.size());
  for (int64_t i = 0; i < v.voxelCount(); ++i) r.unreachedVoxels += v.inside[size_t(i)] != 0;
  r.unreachedVoxels -= reached;
  if (aborted(0.4)) return r;

  choosePrimitivePoints(v, seed, layers, r);  // step 3
  if (aborted(0.5)) return r;
  std::vector<Member> members = clusterMembers(v, layers, layer, reached, r);  // step 4
  if (aborted(0.8)) return r;
  orderVoxels(members, int(r.primitive.size()), r);  // step 5
  aborted(1.0);
  return r;
}

}  // namespace medial
