/// \file
/// Conversion between the docs/ARCHITECTURE.md §4 skeleton vtkPolyData and medial::Skeleton, and the checks
/// on it.
#pragma once

#include "skeleton/Skeleton.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace medial {

///@{
/// Array and field names of docs/ARCHITECTURE.md §4.
constexpr const char* kRadiusArray = "Radius";
constexpr const char* kEllipsoidAxesArray = "EllipsoidAxes";
constexpr const char* kNodeTypeArray = "NodeType";
constexpr const char* kRootField = "Root";
///@}

/// True when the polydata looks like a skeleton: it has line cells and no polygons or strips.
bool looksLikeSkeleton(vtkPolyData* polyData);

/// Reads nodes, edges (polylines are split into their 2-point segments), `Radius`, `EllipsoidAxes` and
/// `Root`. Returns false with `error` set when the polydata holds polygons, or arrays of the wrong size.
/// Does not validate values: call validateSkeleton for that.
bool skeletonFromPolyData(vtkPolyData* polyData, Skeleton& skeleton, std::string& error);

/// Builds the docs/ARCHITECTURE.md §4 polydata, with `NodeType` computed. Assumes a valid skeleton.
vtkSmartPointer<vtkPolyData> polyDataFromSkeleton(const Skeleton& skeleton);

/// The problems of validateSkeleton joined into one line ("...; ...; and 3 more").
std::string describeProblems(const std::vector<SkeletonProblem>& problems);

}  // namespace medial
