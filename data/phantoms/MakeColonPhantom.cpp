// medial-make-colon-phantom OUTPUT_DIR [VOLUME] [--size WxHxD] [--collapse N] [--gap MM] [--fluid]
// [--no-dicom]: a CT-like colon phantom written as a DICOM series (one CT slice per file, int16 Hounsfield
// units) and, when VOLUME is named, as one file too (.nii.gz, .nii, .mha, .nrrd: ITK's writer by extension),
// for the TSK centerline, its benchmark and the GUI's virtual colonoscopy.
//
// An elliptic body (soft tissue 40 HU, a 10 mm fat layer at -100 HU) in air (-1000 HU) holds an
// air-filled colon (-1000 HU) that runs from the rectum up the sigmoid and the descending colon, across the
// transverse colon and down the ascending colon to the cecum, 8 to 12 mm in radius with a haustral fold
// every 30 mm and four polyps (tissue spheres of radius 3 to 5 mm centred on the wall); Gaussian noise
// (sigma 20 HU, fixed seed) over everything. 206 x 165 x 187 voxels of 0.7 x 0.7 x 1.0 mm; --size scales
// the body and the colon's course to another voxel count (same spacing; the colon's radius by the smallest
// of the three factors, so loops keep their tissue between them): 512x512x400 is a full-size CT with a
// colon about 1 m long. --collapse N removes the air over N stretches of --gap MM (default 10) along the
// axis, evenly spaced, as a collapsed or fluid-filled segment does; their arc lengths go to
// OUTPUT_DIR/gaps.txt; with --fluid they hold contrast-tagged fluid (+300 HU) instead of tissue. The true
// axis
// goes to OUTPUT_DIR/axis.txt ("x y z radius" in mm per line) and the polyps to OUTPUT_DIR/polyps.txt
// ("x y z radius"), so that tests can measure a centerline and find the polyps on the unfolded wall.
// Threshold -1024..-600 HU with the border air dropped gives the colon alone (as in the TSK paper's CT data).
#include <itkGDCMImageIO.h>
#include <itkImage.h>
#include <itkImageFileWriter.h>
#include <itkImageSeriesWriter.h>
#include <itkMetaDataObject.h>
#include <itkNumericSeriesFileNames.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

using Point = std::array<double, 3>;
constexpr int kDefaultSize[3] = {206, 165, 187};
int kSize[3] = {206, 165, 187};  // --size
constexpr double kSpacing[3] = {0.7, 0.7, 1.0};
constexpr double kFluidHu = 300.0;  // contrast-tagged fluid in the collapsed stretches with --fluid

// Control points of the colon's axis in mm, rectum first. Non-adjacent loops keep >= 13 mm of tissue
// between their walls, so that the air forms one tube, and the axis bends with a radius of curvature of at
// least 1.9 times the colon's radius, so that the tube does not fold over itself at a flexure: there the
// lumen's true centre would leave the axis and the axis would be no ground truth. (Found by a local search
// from a hand-drawn colon: length 422 mm, 5..179 mm in z, inside the body's fat layer.)
const std::vector<Point> kControl = {
    {72, 72, 12},   {71, 64, 18},  {65, 46, 38},  {68, 39, 52},  {79, 39, 62},  {102, 47, 70}, {112, 65, 91},
    {109, 67, 147}, {94, 44, 166}, {65, 36, 168}, {38, 52, 164}, {31, 65, 141}, {39, 50, 86},  {48, 80, 41}};

Point catmullRom(const Point& p0, const Point& p1, const Point& p2, const Point& p3, double t) {
  Point p;
  for (int c = 0; c < 3; ++c)
    p[c] = 0.5 * ((2 * p1[c]) + (-p0[c] + p2[c]) * t + (2 * p0[c] - 5 * p1[c] + 4 * p2[c] - p3[c]) * t * t +
                  (-p0[c] + 3 * p1[c] - 3 * p2[c] + p3[c]) * t * t * t);
  return p;
}

struct AxisPoint {
  Point p;
  double radius;
  double arc = 0;  // mm from the rectum
};

// The axis for a volume of kSize voxels: the control points scaled by kSize / kDefaultSize per axis.
std::vector<AxisPoint> colonAxis() {
  double scale[3], smallest = INFINITY;
  for (int c = 0; c < 3; ++c) smallest = std::min(smallest, scale[c] = double(kSize[c]) / kDefaultSize[c]);
  std::vector<Point> control;
  for (const Point& p : kControl) control.push_back({p[0] * scale[0], p[1] * scale[1], p[2] * scale[2]});
  std::vector<Point> points;
  const size_t n = control.size();
  const int steps = int(200 * std::max({scale[0], scale[1], scale[2]}));
  for (size_t i = 0; i + 1 < n; ++i)
    for (int k = 0; k < steps; ++k)
      points.push_back(catmullRom(control[i > 0 ? i - 1 : 0], control[i], control[i + 1],
                                  control[std::min(i + 2, n - 1)], double(k) / steps));
  points.push_back(control.back());
  std::vector<double> arc(points.size(), 0.0);
  for (size_t i = 1; i < points.size(); ++i)
    arc[i] = arc[i - 1] + std::hypot(points[i][0] - points[i - 1][0], points[i][1] - points[i - 1][1],
                                     points[i][2] - points[i - 1][2]);
  std::vector<AxisPoint> axis;
  for (size_t i = 0; i < points.size(); ++i) {
    const double s = arc[i] / arc.back();
    const double base = 8.0 + 4.0 * s;  // rectum 8 mm ... cecum 12 mm
    const double fold = std::pow(std::max(0.0, std::cos(2 * M_PI * arc[i] / 30.0)), 8);  // haustra
    axis.push_back({points[i], smallest * base * (1.0 - 0.18 * fold), arc[i]});
  }
  return axis;
}

// A DICOM UID under the 2.25 root (a number from a fixed-seed generator: the phantom is reproducible).
std::string makeUid(std::mt19937_64& random) { return "2.25." + std::to_string(random() >> 1); }

struct Options {
  std::filesystem::path out;
  std::string volume;  // also written as one file when named
  int collapse = 0;
  double gap = 10.0;  // mm
  bool gapGiven = false;
  bool fluid = false;  // the collapsed stretches hold contrast-tagged fluid instead of tissue
  bool dicom = true;
};

const char kUsage[] =
    "usage: medial-make-colon-phantom OUTPUT_DIR [VOLUME.nii.gz|.mha|.nrrd] [--size WxHxD] [--collapse N]\n"
    "                                 [--gap MM] [--fluid] [--no-dicom]\n";

const char kHelp[] =
    "\n"
    "Writes a CT-like colon phantom: an elliptic body (soft tissue 40 HU, a 10 mm fat layer at -100 HU) in\n"
    "air, holding an air-filled colon (-1000 HU) from the rectum to the cecum, 8 to 12 mm in radius, with a\n"
    "haustral fold every 30 mm, four polyps and Gaussian noise (sigma 20 HU). 206 x 165 x 187 voxels of\n"
    "0.7 x 0.7 x 1.0 mm. `medial centerline OUTPUT_DIR -o c.vtp` follows its air.\n"
    "  OUTPUT_DIR        a DICOM series (one int16 CT slice per file, Hounsfield units), axis.txt (the true\n"
    "                    axis, \"x y z radius\" in mm per line), polyps.txt (\"x y z radius\") and, with\n"
    "                    --collapse, gaps.txt (the collapsed stretches' arc lengths, mm)\n"
    "  VOLUME            the same CT as one file too (.nii.gz .nii .mha .nrrd)\n"
    "  --size WxHxD      another voxel count at the same spacing, each 32..4096 (512x512x400: a full-size\n"
    "                    CT with a colon about 1 m long)\n"
    "  --collapse N      N evenly spaced stretches (0..20) of the colon without air, as collapsed segments\n"
    "  --gap MM          length of each collapsed stretch along the axis (default 10, up to 200)\n"
    "  --fluid           the collapsed stretches hold contrast-tagged fluid (+300 HU) instead of tissue\n"
    "  --no-dicom        no DICOM series (VOLUME then required)\n"
    "  -h, --help        this text\n";

// A whole number in [low, high], or false.
bool parseInt(const std::string& text, int low, int high, int& value) {
  char* end = nullptr;
  const long parsed = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || parsed < low || parsed > high) return false;
  value = int(parsed);
  return true;
}

// Parses the command line into `options`; false (after a message) on a usage error.
bool parse(int argc, char** argv, Options& options) {
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string { return i + 1 < argc ? argv[++i] : std::string(); };
    if (arg == "--size") {
      const std::string v = value();
      if (std::sscanf(v.c_str(), "%dx%dx%d", &kSize[0], &kSize[1], &kSize[2]) != 3 || kSize[0] < 32 ||
          kSize[1] < 32 || kSize[2] < 32 || kSize[0] > 4096 || kSize[1] > 4096 || kSize[2] > 4096) {
        std::fprintf(stderr, "medial-make-colon-phantom: --size expects WxHxD, each 32..4096, got '%s'\n",
                     v.c_str());
        return false;
      }
    } else if (arg == "--collapse") {
      if (!parseInt(value(), 0, 20, options.collapse)) {
        std::fprintf(stderr, "medial-make-colon-phantom: --collapse expects 0..20\n");
        return false;
      }
    } else if (arg == "--gap") {
      const std::string v = value();
      options.gapGiven = true;
      char* end = nullptr;
      options.gap = std::strtod(v.c_str(), &end);
      if (v.empty() || *end != '\0' || !(options.gap > 0 && options.gap <= 200)) {
        std::fprintf(stderr, "medial-make-colon-phantom: --gap expects 0..200 mm\n");
        return false;
      }
    } else if (arg == "--fluid") {
      options.fluid = true;
    } else if (arg == "--no-dicom") {
      options.dicom = false;
    } else if (arg.rfind("-", 0) == 0) {
      std::fprintf(stderr, "medial-make-colon-phantom: unknown option %s\n%s", arg.c_str(), kUsage);
      return false;
    } else {
      positional.push_back(arg);
    }
  }
  if (positional.empty() || positional.size() > 2 || (!options.dicom && positional.size() < 2)) {
    std::fprintf(stderr, "%s", kUsage);
    return false;
  }
  if (options.collapse == 0 && (options.fluid || options.gapGiven)) {
    std::fprintf(stderr,
                 "medial-make-colon-phantom: --fluid and --gap shape collapsed stretches: give "
                 "--collapse N too\n");
    return false;
  }
  options.out = positional[0];
  if (positional.size() == 2) options.volume = positional[1];
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::printf("%s%s", kUsage, kHelp);
      return 0;
    }
  Options options;
  if (!parse(argc, argv, options)) return 2;
  const std::filesystem::path& out = options.out;
  std::filesystem::create_directories(out);

  // Air inside the colon: balls along the axis, except over the collapsed stretches (a ball is left out
  // when it reaches into one, so the air ends at the stretch's ends on the axis).
  const std::vector<AxisPoint> axis = colonAxis();
  std::vector<std::pair<double, double>> gaps;
  for (int k = 0; k < options.collapse; ++k) {
    const double middle = axis.back().arc * (k + 1) / (options.collapse + 1);
    gaps.push_back({middle - 0.5 * options.gap, middle + 0.5 * options.gap});
  }
  std::vector<unsigned char> colon(size_t(kSize[0]) * kSize[1] * kSize[2], 0);
  for (const AxisPoint& a : axis) {
    const bool inGap = std::any_of(gaps.begin(), gaps.end(), [&](const std::pair<double, double>& g) {
      return a.arc + a.radius > g.first && a.arc - a.radius < g.second;
    });
    if (inGap && !options.fluid) continue;
    const unsigned char content = inGap ? 2 : 1;  // 2: tagged fluid
    int lo[3], hi[3];
    for (int c = 0; c < 3; ++c) {
      lo[c] = std::max(0, static_cast<int>(std::floor((a.p[c] - a.radius) / kSpacing[c])));
      hi[c] = std::min(kSize[c] - 1, static_cast<int>(std::ceil((a.p[c] + a.radius) / kSpacing[c])));
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) {
          const double dx = x * kSpacing[0] - a.p[0], dy = y * kSpacing[1] - a.p[1],
                       dz = z * kSpacing[2] - a.p[2];
          unsigned char& voxel = colon[(size_t(z) * kSize[1] + y) * kSize[0] + x];
          if (dx * dx + dy * dy + dz * dz <= a.radius * a.radius && voxel != 1) voxel = content;
        }
  }

  // Polyps: tissue spheres centred on the wall at a few places along the colon, on alternating sides.
  std::vector<AxisPoint> polyps;
  const double polypAt[4] = {0.2, 0.45, 0.65, 0.85}, polypRadius[4] = {3.0, 4.0, 5.0, 3.5};
  for (int n = 0; n < 4; ++n) {
    const size_t i = size_t(polypAt[n] * double(axis.size() - 1));
    const Point& a = axis[i - 1].p;
    const Point& b = axis[i + 1].p;
    const double t[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    // A direction perpendicular to the tangent: tangent x (x axis), or x (y axis) when nearly parallel.
    double side[3] = {0, t[2], -t[1]};
    if (std::hypot(side[1], side[2]) < 0.3 * std::hypot(t[0], t[1], t[2]))
      side[0] = -t[2], side[1] = 0, side[2] = t[0];
    const double norm = std::hypot(side[0], side[1], side[2]) * (n % 2 ? -1.0 : 1.0);
    const Point centre = {axis[i].p[0] + axis[i].radius * side[0] / norm,
                          axis[i].p[1] + axis[i].radius * side[1] / norm,
                          axis[i].p[2] + axis[i].radius * side[2] / norm};
    polyps.push_back({centre, polypRadius[n]});
    const double r = polypRadius[n];
    for (int z = std::max(0, int((centre[2] - r) / kSpacing[2]));
         z <= std::min(kSize[2] - 1, int((centre[2] + r) / kSpacing[2]) + 1); ++z)
      for (int y = std::max(0, int((centre[1] - r) / kSpacing[1]));
           y <= std::min(kSize[1] - 1, int((centre[1] + r) / kSpacing[1]) + 1); ++y)
        for (int x = std::max(0, int((centre[0] - r) / kSpacing[0]));
             x <= std::min(kSize[0] - 1, int((centre[0] + r) / kSpacing[0]) + 1); ++x)
          if (std::hypot(x * kSpacing[0] - centre[0], y * kSpacing[1] - centre[1],
                         z * kSpacing[2] - centre[2]) <= r)
            colon[(size_t(z) * kSize[1] + y) * kSize[0] + x] = 0;
  }

  using Volume = itk::Image<int16_t, 3>;
  auto volume = Volume::New();
  Volume::RegionType region;
  region.SetSize({static_cast<itk::SizeValueType>(kSize[0]), static_cast<itk::SizeValueType>(kSize[1]),
                  static_cast<itk::SizeValueType>(kSize[2])});
  volume->SetRegions(region);
  volume->SetSpacing(kSpacing);
  volume->Allocate();
  std::mt19937 random(20081);
  std::normal_distribution<double> noise(0.0, 20.0);
  const double cx = 0.5 * (kSize[0] - 1) * kSpacing[0], cy = 0.5 * (kSize[1] - 1) * kSpacing[1];
  const double ax = 66.0 * kSize[0] / kDefaultSize[0], ay = 52.0 * kSize[1] / kDefaultSize[1];  // body (mm)
  for (int z = 0; z < kSize[2]; ++z)
    for (int y = 0; y < kSize[1]; ++y)
      for (int x = 0; x < kSize[0]; ++x) {
        const double u = (x * kSpacing[0] - cx) / ax, v = (y * kSpacing[1] - cy) / ay;
        const double rho = std::sqrt(u * u + v * v);  // 1 on the skin
        double hu = rho > 1.0 ? -1000.0 : rho > 1.0 - 10.0 / ay ? -100.0 : 40.0;
        const unsigned char inColon = colon[(size_t(z) * kSize[1] + y) * kSize[0] + x];
        if (inColon) hu = inColon == 2 ? kFluidHu : -1000.0;
        hu = std::clamp(hu + noise(random), -1024.0, 3071.0);
        volume->SetPixel({x, y, z}, static_cast<int16_t>(std::lround(hu)));
      }

  // One DICOM file per axial slice; position, orientation and spacing per slice so that readers sort and
  // place them (GDCMSeriesFileNames orders by Image Position Patient).
  auto io = itk::GDCMImageIO::New();
  std::mt19937_64 uids(2008);
  const std::string study = makeUid(uids), series = makeUid(uids), frame = makeUid(uids);
  using Slice = itk::Image<int16_t, 2>;
  using Writer = itk::ImageSeriesWriter<Volume, Slice>;
  Writer::DictionaryArrayType dictionaries;
  std::vector<std::unique_ptr<itk::MetaDataDictionary>> owned;
  for (int z = 0; z < kSize[2]; ++z) {
    owned.push_back(std::make_unique<itk::MetaDataDictionary>());
    itk::MetaDataDictionary& d = *owned.back();
    auto set = [&d](const char* tag, const std::string& value) {
      itk::EncapsulateMetaData<std::string>(d, tag, value);
    };
    char text[128];
    set("0008|0060", "CT");
    set("0010|0010", "Colon^Phantom");
    set("0010|0020", "MEDIAL-COLON-1");
    set("0008|103e", "Medial CT colon phantom");
    set("0020|000d", study);
    set("0020|000e", series);
    set("0020|0052", frame);
    set("0008|0018", makeUid(uids));
    std::snprintf(text, sizeof text, "%d", z + 1);
    set("0020|0013", text);
    std::snprintf(text, sizeof text, "0\\0\\%.4f", z * kSpacing[2]);
    set("0020|0032", text);
    set("0020|0037", "1\\0\\0\\0\\1\\0");
    std::snprintf(text, sizeof text, "%.4f\\%.4f", kSpacing[1], kSpacing[0]);
    set("0028|0030", text);
    std::snprintf(text, sizeof text, "%.4f", kSpacing[2]);
    set("0018|0050", text);
    set("0028|0004", "MONOCHROME2");
    set("0028|1052", "0");
    set("0028|1053", "1");
    dictionaries.push_back(&d);
  }
  auto names = itk::NumericSeriesFileNames::New();
  names->SetSeriesFormat((out / "slice%03d.dcm").string());
  names->SetStartIndex(1);
  names->SetEndIndex(kSize[2]);
  names->SetIncrementIndex(1);
  auto writer = Writer::New();
  writer->SetInput(volume);
  writer->SetImageIO(io);
  writer->SetFileNames(names->GetFileNames());
  writer->SetMetaDataDictionaryArray(&dictionaries);
  try {
    if (options.dicom) writer->Update();
  } catch (const itk::ExceptionObject& e) {
    std::fprintf(stderr, "medial-make-colon-phantom: %s\n", e.GetDescription());
    return 1;
  }

  if (!options.volume.empty()) {
    auto file = itk::ImageFileWriter<Volume>::New();
    file->SetInput(volume);
    file->SetFileName(options.volume);
    try {
      file->Update();
    } catch (const itk::ExceptionObject& e) {
      std::fprintf(stderr, "medial-make-colon-phantom: %s: %s\n", options.volume.c_str(), e.GetDescription());
      return 1;
    }
  }
  if (!gaps.empty()) {
    std::ofstream gapFile(out / "gaps.txt");
    gapFile << "# collapsed segments: start and end arc length (mm) along axis.txt\n";
    for (const auto& [start, end] : gaps) gapFile << start << ' ' << end << '\n';
  }
  std::ofstream polypFile(out / "polyps.txt");
  polypFile << "# polyps: centre x y z and radius (mm)\n";
  for (const AxisPoint& p : polyps)
    polypFile << p.p[0] << ' ' << p.p[1] << ' ' << p.p[2] << ' ' << p.radius << '\n';
  std::ofstream axisFile(out / "axis.txt");
  axisFile << "# true colon axis, rectum first: x y z radius (mm)\n";
  for (const AxisPoint& a : axis)
    axisFile << a.p[0] << ' ' << a.p[1] << ' ' << a.p[2] << ' ' << a.radius << '\n';
  std::printf("wrote %dx%dx%d voxels: %s%s%s%s, axis.txt and polyps.txt%s to %s\n", kSize[0], kSize[1],
              kSize[2], options.dicom ? "DICOM slices" : "",
              options.dicom && !options.volume.empty() ? " and " : "", options.volume.c_str(), "",
              gaps.empty() ? "" : ", gaps.txt", out.string().c_str());
  return 0;
}
