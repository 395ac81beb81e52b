#include "ProfileChart.h"

#include "MedialAxisTicks.h"
#include "MedialFileNames.h"
#include "MedialProfileCsv.h"
#include "MedialTerrainImage.h"

#include <QEvent>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QMouseEvent>
#include <QPen>
#include <QPushButton>
#include <QVBoxLayout>
#include <QtCharts/QChart>
#include <QtCharts/QChartView>
#include <QtCharts/QLegendMarker>
#include <QtCharts/QLineSeries>
#include <QtCharts/QScatterSeries>
#include <QtCharts/QValueAxis>

#include <vtkDataArray.h>
#include <vtkTable.h>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace medial::gui {

namespace {

// Round ticks (1, 2 or 5 x 10^k) on a value axis, labelled with the step's decimals.
void setRoundTicks(QValueAxis* axis, double low, double high, int target) {
  const medial::AxisTicks ticks = medial::roundTicks(low, high, target);
  axis->setRange(low, high);
  axis->setTickType(QValueAxis::TicksDynamic);
  axis->setTickAnchor(0);
  axis->setTickInterval(ticks.step);
  const int decimals = std::max(0, int(std::ceil(-std::log10(ticks.step) - 1e-9)));
  axis->setLabelFormat(QString("%.%1f").arg(decimals));
}

std::vector<double> column(vtkTable* table, const char* name) {
  std::vector<double> values;
  if (auto* array = vtkDataArray::SafeDownCast(table ? table->GetColumnByName(name) : nullptr))
    for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i) values.push_back(array->GetComponent(i, 0));
  return values;
}

}  // namespace

ProfileChart::ProfileChart(QWidget* parent) : QWidget(parent) {
  minDiameter_ = new QLineSeries;
  minDiameter_->setName("min diameter");
  maxDiameter_ = new QLineSeries;
  maxDiameter_->setName("max diameter");
  marker_ = new QLineSeries;
  marker_->setName("camera");
  marker_->setPen(QPen(QColor(200, 0, 0), 1.5, Qt::DashLine));  // not the bridges' orange
  bridged_ = new QScatterSeries;
  bridged_->setName("bridged (no lumen)");
  bridged_->setColor(QColor(medial::kBridgedRgb[0], medial::kBridgedRgb[1], medial::kBridgedRgb[2]));
  bridged_->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
  bridged_->setMarkerSize(6);
  bridged_->setBorderColor(Qt::transparent);
  auto* chart = new QChart;
  for (QAbstractSeries* series :
       std::initializer_list<QAbstractSeries*>{minDiameter_, maxDiameter_, marker_, bridged_})
    chart->addSeries(series);
  chart->createDefaultAxes();
  chart->legend()->setAlignment(Qt::AlignBottom);
  chart->legend()->markers(marker_).first()->setVisible(false);
  chart->setTitle("Section diameter (mm) along the centerline");
  chart->setMargins(QMargins(2, 2, 2, 2));
  QFont small = chart->font();
  small.setPointSizeF(small.pointSizeF() * 0.85);
  for (QAbstractAxis* axis : chart->axes()) {
    axis->setLabelsFont(small);
    axis->setTitleFont(small);
  }
  chart->axes(Qt::Horizontal).first()->setTitleText("arc length (mm)");
  view_ = new QChartView(chart, this);
  view_->setObjectName("profile");
  view_->setMinimumHeight(200);
  view_->setRenderHint(QPainter::Antialiasing);
  view_->viewport()->setMouseTracking(true);
  view_->viewport()->installEventFilter(this);
  view_->setToolTip("Move the mouse for a section's measures; click to fly there");

  readout_ = new QLabel("Point at the profile", this);
  readout_->setObjectName("profileReadout");
  readout_->setSizePolicy(QSizePolicy::Ignored,
                          QSizePolicy::Preferred);  // long text does not widen the panel
  auto* csv = new QPushButton("CSV...", this);
  csv->setObjectName("exportProfileCsv");
  csv->setToolTip("Save the profile as CSV (as medial centerline --profile writes it)");
  auto* png = new QPushButton("PNG...", this);
  png->setObjectName("exportProfilePng");
  png->setToolTip("Save the chart as a PNG picture");
  connect(csv, &QPushButton::clicked, this, [this] { exportWithDialog(true); });
  connect(png, &QPushButton::clicked, this, [this] { exportWithDialog(false); });
  auto* row = new QHBoxLayout;
  row->addWidget(readout_, 1);
  row->addWidget(csv);
  row->addWidget(png);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(view_);
  layout->addLayout(row);
}

void ProfileChart::setProfile(vtkTable* profile) {
  arc_ = column(profile, "ArcLength");
  min_ = column(profile, "MinDiameter");
  max_ = column(profile, "MaxDiameter");
  area_ = column(profile, "Area");
  const std::vector<double> gap = column(profile, "Bridged");
  csv_ = medial::profileCsv(profile);
  if (min_.size() != arc_.size() || max_.size() != arc_.size()) arc_.clear();
  isBridged_.assign(arc_.size(), 0);
  QList<QPointF> lows, highs, bridges;
  std::vector<double> maxima;
  for (size_t i = 0; i < arc_.size(); ++i) {
    isBridged_[i] = i < gap.size() && gap[i] != 0;
    if (isBridged_[i]) bridges.append(QPointF(arc_[i], 0));
    if (!std::isfinite(min_[i]) || !std::isfinite(max_[i])) continue;
    lows.append(QPointF(arc_[i], min_[i]));
    highs.append(QPointF(arc_[i], max_[i]));
    maxima.push_back(max_[i]);
  }
  minDiameter_->replace(lows);
  maxDiameter_->replace(highs);
  bridged_->replace(bridges);
  // The axis ends above the 95th percentile of the max diameter: oblique cuts at sharp bends spike it.
  top_ = 1;
  if (!maxima.empty()) {
    std::sort(maxima.begin(), maxima.end());
    top_ = std::max(top_, 1.1 * maxima[maxima.size() * 95 / 100]);
  }
  const double length = arc_.empty() ? 1.0 : std::max(arc_.back(), 1.0);
  auto* horizontal = static_cast<QValueAxis*>(view_->chart()->axes(Qt::Horizontal).first());
  auto* vertical = static_cast<QValueAxis*>(view_->chart()->axes(Qt::Vertical).first());
  setRoundTicks(horizontal, 0, length, 6);
  setRoundTicks(vertical, 0, top_, 5);
  setMarker(0);
}

void ProfileChart::setMarker(double arcLength) {
  marker_->replace(QList<QPointF>{{arcLength, 0}, {arcLength, top_}});
}

int ProfileChart::points() const { return static_cast<int>(maxDiameter_->count()); }

int ProfileChart::bridgedPoints() const { return static_cast<int>(bridged_->count()); }

size_t ProfileChart::nearestSection(double arcLength) const {
  const auto next = std::lower_bound(arc_.begin(), arc_.end(), arcLength);
  size_t i = std::min<size_t>(next - arc_.begin(), arc_.size() - 1);
  if (i > 0 && arcLength - arc_[i - 1] < arc_[i] - arcLength) --i;
  return i;
}

QString ProfileChart::readoutAt(double arcLength) const {
  if (arc_.empty()) return {};
  const size_t i = nearestSection(arcLength);
  if (isBridged_[i]) return QString("arc %1 mm: bridged gap, no lumen").arg(arc_[i], 0, 'f', 0);
  if (!std::isfinite(min_[i]) || !std::isfinite(max_[i]))
    return QString("arc %1 mm: no wall found on some rays").arg(arc_[i], 0, 'f', 0);
  QString text = QString("arc %1 mm: min %2 mm, max %3 mm")
                     .arg(arc_[i], 0, 'f', 0)
                     .arg(min_[i], 0, 'f', 1)
                     .arg(max_[i], 0, 'f', 1);
  if (i < area_.size() && std::isfinite(area_[i])) text += QString(", area %1 mm²").arg(area_[i], 0, 'f', 0);
  return text;
}

QString ProfileChart::readout() const { return readout_->text(); }

double ProfileChart::arcLengthAt(const QPoint& viewportPoint) const {
  const QPointF scene = view_->mapToScene(viewportPoint);
  return view_->chart()->mapToValue(view_->chart()->mapFromScene(scene), minDiameter_).x();
}

bool ProfileChart::eventFilter(QObject* watched, QEvent* event) {
  if (watched == view_->viewport() && !arc_.empty()) {
    if (event->type() == QEvent::MouseMove) {
      readout_->setText(readoutAt(arcLengthAt(static_cast<QMouseEvent*>(event)->position().toPoint())));
    } else if (event->type() == QEvent::MouseButtonPress &&
               static_cast<QMouseEvent*>(event)->button() == Qt::LeftButton) {
      const double arc = arcLengthAt(static_cast<QMouseEvent*>(event)->position().toPoint());
      if (arc >= 0 && arc <= arc_.back()) emit clicked(arc);
    }
  }
  return QWidget::eventFilter(watched, event);
}

bool ProfileChart::exportCsv(const QString& path, QString& error) const {
  if (csv_.empty()) {
    error = "no profile yet: run the centerline first";
    return false;
  }
  std::string why;
  const auto write = [this](const std::string& temporary, std::string& reason) {
    std::ofstream out(temporary);
    if (!(out << csv_) || !out.flush()) reason = "cannot write the file";
    return reason.empty();
  };
  if (!medial::writeAtomically(path.toStdString(), write, why)) error = QString::fromStdString(why);
  return error.isEmpty();
}

bool ProfileChart::exportPng(const QString& path) const { return view_->grab().save(path, "PNG"); }

void ProfileChart::exportWithDialog(bool csv) {
  const QString path = QFileDialog::getSaveFileName(this, csv ? "Save the profile" : "Save the chart",
                                                    csv ? "profile.csv" : "profile.png",
                                                    csv ? "CSV (*.csv)" : "PNG pictures (*.png)");
  if (path.isEmpty()) return;
  QString error;
  const bool ok = csv ? exportCsv(path, error) : exportPng(path);
  if (!ok)
    QMessageBox::warning(this, "Export", path + ": " + (error.isEmpty() ? "cannot write the file" : error));
}

}  // namespace medial::gui
