// Sketch skeletonization against CGAL's straight skeleton (docs/ARCHITECTURE.md §8, issue 7): per part of
// each sketch, the median time of Medial's chain of stages 1-3 and 6 (stroke preparation, straight skeleton,
// BoundedDP, refinement; no inflation) beside CGAL's interior straight skeleton alone on the same polygon:
// the stroke as drawn (when it is simple), the stroke resampled (what a user would feed CGAL to avoid jitter)
// and the simplified polygon Medial itself skeletonizes (CGAL with exact predicates, Epick, as a user would
// call it).
//
// usage: medial_bench_sketch [--repeat N] [--medial-only] SKETCH.txt...   (--medial-only: no CGAL columns,
// for profiling Medial's chain alone)
#include "MedianSeconds.h"

#include "sketch/SketchSkeleton.h"
#include "sketch/StraightSkeletonGraph.h"
#include "vtkMedialSketchReader.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

std::vector<medial::Polygon2> readStrokes(const std::string& path) {
  auto reader = vtkSmartPointer<vtkMedialSketchReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  std::vector<medial::Polygon2> strokes;
  vtkPolyData* data = reader->GetOutput();
  auto ids = vtkSmartPointer<vtkIdList>::New();
  vtkCellArray* lines = data->GetLines();
  for (lines->InitTraversal(); lines->GetNextCell(ids);) {
    strokes.emplace_back();
    for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k) {  // the last id closes the loop
      double p[3];
      data->GetPoint(ids->GetId(k), p);
      strokes.back().emplace_back(p[0], p[1]);
    }
  }
  return strokes;
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 21;
  bool medialOnly = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--repeat" && i + 1 < argc)
      repeat = std::max(1, std::atoi(argv[++i]));
    else if (arg == "--medial-only")
      medialOnly = true;
    else
      files.push_back(arg);
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: medial_bench_sketch [--repeat N] [--medial-only] SKETCH.txt...\n");
    return 2;
  }
  std::printf("%-14s %4s %6s %6s %10s %10s %10s %10s %9s %9s %9s\n", "sketch", "part", "points", "polygon",
              "medial ms", "cgal-raw", "cgal-res", "cgal-poly", "ratio-raw", "ratio-res", "ratio-poly");
  std::vector<double> medialTimes;
  for (const std::string& file : files) {
    const auto strokes = readStrokes(file);
    const std::string name = file.substr(file.find_last_of('/') + 1);
    for (size_t k = 0; k < strokes.size(); ++k) {
      medial::SketchPart part;
      part.stroke = strokes[k];
      medial::SketchParameters p;
      p.inflate = false;
      medial::SketchResult result;
      const double medial = medianSeconds(repeat, [&] { result = medial::sketchSkeleton({part}, p); });
      if (!result.ok()) {
        std::fprintf(stderr, "%s part %zu: %s\n", name.c_str(), k + 1, result.error.message().c_str());
        return 1;
      }
      medialTimes.push_back(medial);
      if (medialOnly) {
        std::printf("%-14s %4zu %6zu %6zu %10.3f\n", name.c_str(), k + 1, strokes[k].size(),
                    result.parts[0].stroke.polygon.size(), 1e3 * medial);
        continue;
      }
      medial::Polygon2 raw = strokes[k];
      if (medial::signedArea(raw) < 0) std::reverse(raw.begin(), raw.end());
      const bool rawSimple = medial::findSelfIntersection(raw).first < 0;
      const double cgalRaw =
          rawSimple ? medianSeconds(repeat, [&] { medial::cgalStraightSkeletonVertexCount(raw); }) : 0;
      const auto& resampled = result.parts[0].stroke.resampled;
      // CGAL takes seconds on a dense polygon: fewer runs for this column.
      const double cgalResampled =
          medianSeconds(std::min(repeat, 3), [&] { medial::cgalStraightSkeletonVertexCount(resampled); });
      const double cgalPolygon = medianSeconds(
          repeat, [&] { medial::cgalStraightSkeletonVertexCount(result.parts[0].stroke.polygon); });
      char rawTime[32] = "n/a", rawRatio[32] = "n/a";
      if (rawSimple) {
        std::snprintf(rawTime, sizeof rawTime, "%.3f", 1e3 * cgalRaw);
        std::snprintf(rawRatio, sizeof rawRatio, "%.2f", medial / cgalRaw);
      }
      std::printf("%-14s %4zu %6zu %6zu %10.3f %10s %10.3f %10.3f %9s %9.2f %9.2f\n", name.c_str(), k + 1,
                  strokes[k].size(), result.parts[0].stroke.polygon.size(), 1e3 * medial, rawTime,
                  1e3 * cgalResampled, 1e3 * cgalPolygon, rawRatio, medial / cgalResampled,
                  medial / cgalPolygon);
    }
  }
  std::sort(medialTimes.begin(), medialTimes.end());
  std::printf(
      "median per part: %.3f ms, slowest part %.3f ms, over %zu parts (goal <= 2 ms per part; the paper: "
      "8.8 ms on average)\n",
      1e3 * medialTimes[medialTimes.size() / 2], 1e3 * medialTimes.back(), medialTimes.size());
  return 0;
}
