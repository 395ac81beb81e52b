// Writing a command's polydata output, shared by the commands.
#pragma once

#include <string>

class vtkMedialRigWriter;
class vtkPolyData;

namespace medial::cli {

// Writes by extension through vtkMedialPolyDataWriter (atomic); throws Failure with the writer's errors.
void writePolyData(vtkPolyData* data, const std::string& path);

// Writes the polylines of `centerline` as 3D Slicer markups curves (vtkMedialMarkupsCurveWriter);
// throws Failure with the writer's errors.
void writeMarkups(vtkPolyData* centerline, const std::string& path);

// Throws UsageError naming `option` when vtkMedialPolyDataWriter cannot write `path`'s extension.
void requireWritableExtension(const std::string& path, const char* option);

// Writes the skinned mesh (point data SkinWeights) and its skeleton as a rig through `writer` (configured
// by the caller: MaxInfluences); throws Failure with the writer's errors.
void writeRig(vtkMedialRigWriter* writer, vtkPolyData* mesh, vtkPolyData* skeleton, const std::string& path);

// Writes `text` to `path` atomically; throws Failure naming the file.
void writeText(const std::string& text, const std::string& path);

// Makes the directory of an option that writes several files (--contraction-steps, --stages) before any
// work; throws UsageError for an empty name and Failure when it cannot be made.
void makeOutputDirectory(const std::string& dir, const char* option);

}  // namespace medial::cli
