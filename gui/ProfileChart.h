// ProfileChart: the diameter profile along a centerline (paper §4, Fig. 14) as a chart a user reads and
// keeps: the sections' min and max diameter over the arc length with round ticks, the bridged sections
// marked, the fly-through camera as a vertical line, a readout of the section under the mouse, a click
// that moves the fly-through there, and CSV and PNG export.
#pragma once

#include <QString>
#include <QWidget>

#include <vector>

class QChartView;
class QLabel;
class QLineSeries;
class QScatterSeries;
class vtkTable;

namespace medial::gui {

class ProfileChart : public QWidget {
  Q_OBJECT

 public:
  explicit ProfileChart(QWidget* parent = nullptr);

  // The filter's profile table (port 1); nullptr clears the chart.
  void setProfile(vtkTable* profile);
  // The fly-through camera's arc length (mm), drawn as a vertical line.
  void setMarker(double arcLength);

  int points() const;         // sections with a measured diameter
  int bridgedPoints() const;  // sections on bridges across gaps
  // "arc 123 mm: min 18.2 mm, max 22.4 mm, area 310 mm²" for the section nearest `arcLength`.
  QString readoutAt(double arcLength) const;
  QString readout() const;
  // The arc length (mm) under a point of the chart view's viewport.
  double arcLengthAt(const QPoint& viewportPoint) const;
  QChartView* view() const { return view_; }
  bool exportCsv(const QString& path, QString& error) const;
  bool exportPng(const QString& path) const;

 signals:
  void clicked(double arcLength);

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void exportWithDialog(bool csv);
  size_t nearestSection(double arcLength) const;

  QChartView* view_ = nullptr;
  QLineSeries* minDiameter_ = nullptr;
  QLineSeries* maxDiameter_ = nullptr;
  QLineSeries* marker_ = nullptr;
  QScatterSeries* bridged_ = nullptr;
  QLabel* readout_ = nullptr;
  std::vector<double> arc_, min_, max_, area_;
  std::vector<char> isBridged_;
  std::string csv_;  // the profile as the CLI's --profile writes it
  double top_ = 1;   // the diameter axis's top (mm)
};

}  // namespace medial::gui
