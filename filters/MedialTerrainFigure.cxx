#include "MedialTerrainFigure.h"

#include "MedialAxisTicks.h"
#include "MedialTerrainImage.h"

#include <vtkFreeTypeTools.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace medial {

namespace {

// An RGB picture with row 0 at the top, and what the figure draws on it.
struct Canvas {
  int width, height;
  std::vector<uint8_t> rgb;
  Canvas(int w, int h) : width(w), height(h), rgb(size_t(w) * h * 3, 255) {}

  uint8_t* at(int x, int y) { return &rgb[(size_t(y) * width + x) * 3]; }
  void fill(int x0, int y0, int x1, int y1, const uint8_t colour[3]) {
    for (int y = std::max(0, y0); y < std::min(height, y1); ++y)
      for (int x = std::max(0, x0); x < std::min(width, x1); ++x) std::copy(colour, colour + 3, at(x, y));
  }
  // `text` with its box's anchor at (x, y): align 0 = left/top, 0.5 = centre, 1 = right/bottom; vertical
  // text (rotated 90 degrees) reads upwards.
  void text(const std::string& text, int x, int y, double alignX, double alignY, bool vertical = false) {
    auto property = vtkSmartPointer<vtkTextProperty>::New();
    property->SetFontSize(13);
    property->SetColor(0.1, 0.1, 0.1);
    property->SetOrientation(vertical ? 90 : 0);
    auto glyphs = vtkSmartPointer<vtkImageData>::New();
    int dims[2];
    if (!vtkFreeTypeTools::GetInstance()->RenderString(property, text, 72, glyphs, dims)) return;
    int extent[6];
    glyphs->GetExtent(extent);
    // The inked box (the image is padded to a power of two), VTK's rows going up.
    int box[4] = {extent[1], extent[0], extent[3], extent[2]};
    for (int j = extent[2]; j <= extent[3]; ++j)
      for (int i = extent[0]; i <= extent[1]; ++i)
        if (static_cast<uint8_t*>(glyphs->GetScalarPointer(i, j, 0))[3] > 0) {
          box[0] = std::min(box[0], i), box[1] = std::max(box[1], i);
          box[2] = std::min(box[2], j), box[3] = std::max(box[3], j);
        }
    if (box[0] > box[1]) return;
    const int left = x - int(std::lround(alignX * (box[1] - box[0] + 1)));
    const int top = y - int(std::lround(alignY * (box[3] - box[2] + 1)));
    for (int j = box[2]; j <= box[3]; ++j)
      for (int i = box[0]; i <= box[1]; ++i) {
        const int px = left + i - box[0], py = top + box[3] - j;
        if (px < 0 || py < 0 || px >= width || py >= height) continue;
        const auto* ink = static_cast<uint8_t*>(glyphs->GetScalarPointer(i, j, 0));
        const double a = ink[3] / 255.0;
        uint8_t* out = at(px, py);
        for (int c = 0; c < 3; ++c) out[c] = uint8_t(std::lround((1 - a) * out[c] + a * ink[c]));
      }
  }
};

constexpr uint8_t kInk[3] = {25, 25, 25};
constexpr int kLeft = 84, kTop = 46, kPanelWidth = 360, kRight = 132, kBottom = 40;

// The wall at angle pixel x (linear between rays, wrapping round) and section row `section`.
void panelColour(const TerrainGrey& grey, int x, int section, uint8_t rgb[3]) {
  const double ray = (x + 0.5) * grey.width / kPanelWidth - 0.5;
  const int r0 = int(std::floor(ray)), r1 = r0 + 1;
  const double f = ray - r0;
  const int a = (r0 + grey.width) % grey.width, b = r1 % grey.width;
  const size_t row = size_t(section) * grey.width;
  if (grey.bridged[size_t(section)] || grey.noWall[row + a] || grey.noWall[row + b]) {
    terrainPixelColour(grey, row + (f < 0.5 ? a : b), rgb);
    return;
  }
  terrainColour(uint8_t(std::lround((1 - f) * grey.pixels[row + a] + f * grey.pixels[row + b])), rgb);
}

void drawPanel(Canvas& canvas, const TerrainGrey& grey, int panelHeight) {
  for (int y = 0; y < panelHeight; ++y) {
    const int section = std::min(grey.height - 1, int((y + 0.5) * grey.height / panelHeight));
    for (int x = 0; x < kPanelWidth; ++x) panelColour(grey, x, section, canvas.at(kLeft + x, kTop + y));
  }
  canvas.fill(kLeft - 1, kTop - 1, kLeft + kPanelWidth + 1, kTop, kInk);  // frame
  canvas.fill(kLeft - 1, kTop + panelHeight, kLeft + kPanelWidth + 1, kTop + panelHeight + 1, kInk);
  canvas.fill(kLeft - 1, kTop, kLeft, kTop + panelHeight, kInk);
  canvas.fill(kLeft + kPanelWidth, kTop, kLeft + kPanelWidth + 1, kTop + panelHeight, kInk);
}

void drawAxes(Canvas& canvas, int panelHeight, double length) {
  canvas.text("angle around the axis (degrees)", kLeft + kPanelWidth / 2, 4, 0.5, 0);
  for (int degrees = 0; degrees <= 360; degrees += 90) {
    const int x = kLeft + int(std::lround(degrees / 360.0 * kPanelWidth));
    canvas.fill(x - 1, kTop - 6, x + 1, kTop - 1, kInk);
    canvas.text(std::to_string(degrees), x, kTop - 9, 0.5, 1);
  }
  const AxisTicks ticks = roundTicks(0, length, std::max(2, panelHeight / 60));
  for (const double mm : ticks.values) {
    const int y = kTop + int(std::lround(mm / std::max(length, 1e-9) * panelHeight));
    canvas.fill(kLeft - 7, y - 1, kLeft - 1, y + 1, kInk);
    canvas.text(ticks.label(mm), kLeft - 10, y, 1, 0.5);
  }
  canvas.text("arc length from the start (mm)", 8, kTop + panelHeight / 2, 0, 0.5, true);
}

void drawColourBar(Canvas& canvas, const TerrainGrey& grey, int panelHeight) {
  const int x0 = kLeft + kPanelWidth + 22, barHeight = std::min(panelHeight, 300);
  for (int y = 0; y < barHeight; ++y) {
    uint8_t rgb[3];
    terrainColour(uint8_t(std::lround(255.0 * (1 - (y + 0.5) / barHeight))), rgb);  // far at the top
    canvas.fill(x0, kTop + y, x0 + 16, kTop + y + 1, rgb);
  }
  const AxisTicks ticks = roundTicks(grey.low, grey.high, 5);
  for (const double mm : ticks.values) {
    const int y = kTop + int(std::lround((grey.high - mm) / (grey.high - grey.low) * barHeight));
    canvas.fill(x0 + 16, y - 1, x0 + 21, y + 1, kInk);
    canvas.text(ticks.label(mm), x0 + 24, y, 0, 0.5);
  }
  canvas.text("wall distance from the axis (mm)", x0 + 68, kTop + barHeight / 2, 0, 0.5, true);
}

void drawLegend(Canvas& canvas, int y) {
  canvas.fill(kLeft, y, kLeft + 14, y + 12, kBridgedRgb);
  canvas.text("bridged gap (no lumen)", kLeft + 20, y + 6, 0, 0.5);
  canvas.fill(kLeft + 190, y, kLeft + 204, y + 12, kNoWallRgb);
  canvas.text("no wall found", kLeft + 210, y + 6, 0, 0.5);
}

}  // namespace

vtkSmartPointer<vtkImageData> terrainFigure(vtkImageData* terrain) {
  const TerrainGrey grey = terrainGrey(terrain);
  if (grey.pixels.empty()) return nullptr;
  // Three pixels per section up to 1,600 pixels, then one per section (a full colon: about 1,500), then
  // rows shared by several sections beyond 6,000.
  const int panelHeight = std::clamp(std::min(3 * grey.height, std::max(grey.height, 1600)), 1, 6000);
  const double length = terrain->GetSpacing()[1] * std::max(0, grey.height - 1);
  Canvas canvas(kLeft + kPanelWidth + kRight, kTop + panelHeight + kBottom);
  drawPanel(canvas, grey, panelHeight);
  drawAxes(canvas, panelHeight, length);
  drawColourBar(canvas, grey, panelHeight);
  drawLegend(canvas, kTop + panelHeight + 14);

  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(canvas.width, canvas.height, 1);
  auto pixels = vtkSmartPointer<vtkUnsignedCharArray>::New();
  pixels->SetNumberOfComponents(3);
  pixels->SetNumberOfTuples(vtkIdType(canvas.width) * canvas.height);
  for (int y = 0; y < canvas.height; ++y)  // VTK's rows go up: the canvas's top row is the last one
    std::copy_n(canvas.at(0, y), 3 * canvas.width,
                pixels->GetPointer(0) + size_t(canvas.height - 1 - y) * canvas.width * 3);
  image->GetPointData()->SetScalars(pixels);
  return image;
}

}  // namespace medial
