/**
 * @class vtkMedialMeshTopology
 * @brief Tells whether a polygon mesh is a closed 2-manifold, how many components it has and its genus.
 *
 * The output is the input (shallow copy) with field data arrays `Genus`, `EulerCharacteristic`,
 * `Components`, `BorderEdges`, `NonManifoldEdges`, `BoundaryLoops`; the same values are available through
 * the getters after an update. Polygons and triangle strips count as faces; lines and vertices are
 * ignored. Genus is the sum over components of (2 - chi - b) / 2, meaningful for manifold meshes.
 * Implements medial::computeMeshTopology (src/mesh/MeshTopology.h).
 */
#pragma once

#include "MedialFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class MEDIALFILTERS_EXPORT vtkMedialMeshTopology : public vtkPolyDataAlgorithm {
 public:
  static vtkMedialMeshTopology* New();
  vtkTypeMacro(vtkMedialMeshTopology, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkGetMacro(NumberOfFaces, vtkIdType);
  vtkGetMacro(NumberOfEdges, vtkIdType);
  vtkGetMacro(NumberOfBorderEdges, vtkIdType);
  vtkGetMacro(NumberOfNonManifoldEdges, vtkIdType);
  vtkGetMacro(NumberOfComponents, vtkIdType);
  vtkGetMacro(NumberOfBoundaryLoops, vtkIdType);
  vtkGetMacro(EulerCharacteristic, vtkIdType);
  vtkGetMacro(Genus, vtkIdType);
  /// No border and no non-manifold edge, and at least one face.
  vtkGetMacro(ClosedManifold, bool);

 protected:
  vtkMedialMeshTopology() = default;
  ~vtkMedialMeshTopology() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

 private:
  vtkMedialMeshTopology(const vtkMedialMeshTopology&) = delete;
  void operator=(const vtkMedialMeshTopology&) = delete;

  vtkIdType NumberOfFaces = 0;
  vtkIdType NumberOfEdges = 0;
  vtkIdType NumberOfBorderEdges = 0;
  vtkIdType NumberOfNonManifoldEdges = 0;
  vtkIdType NumberOfComponents = 0;
  vtkIdType NumberOfBoundaryLoops = 0;
  vtkIdType EulerCharacteristic = 0;
  vtkIdType Genus = 0;
  bool ClosedManifold = false;
};
