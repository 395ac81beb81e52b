#include "MedialSkeletonTubes.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkGlyph3D.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkSphereSource.h>
#include <vtkTubeFilter.h>

namespace medial {

vtkSmartPointer<vtkActor> skeletonTubesActor(vtkPolyData* skeleton, int sides) {
  auto tubes = vtkSmartPointer<vtkTubeFilter>::New();
  tubes->SetInputData(skeleton);
  tubes->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
  tubes->SetNumberOfSides(sides);
  tubes->CappingOn();
  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(sides);
  sphere->SetPhiResolution(sides * 2 / 3);
  auto balls = vtkSmartPointer<vtkGlyph3D>::New();
  balls->SetInputData(skeleton);
  balls->SetSourceConnection(sphere->GetOutputPort());
  balls->SetScaleModeToScaleByScalar();
  balls->SetScaleFactor(1.0);
  balls->OrientOff();
  auto both = vtkSmartPointer<vtkAppendPolyData>::New();
  both->AddInputConnection(tubes->GetOutputPort());
  both->AddInputConnection(balls->GetOutputPort());
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(both->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

}  // namespace medial
