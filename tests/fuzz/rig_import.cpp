// Fuzz target: medial::importRig on any bytes, as the GUI and vtkMedialReader run it on any .glb, .gltf
// or .fbx a user opens (Assimp underneath). It must give a rig or an error, never crash, hang or allocate
// without bound. The bytes are written under the extension their start suggests: "glTF" a binary glTF,
// "{" a glTF in JSON, anything else FBX.
#include "FuzzFile.h"
#include "rig/RigImport.h"

#include <unistd.h>

#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const char* extension = size >= 4 && std::memcmp(data, "glTF", 4) == 0 ? ".glb"
                          : size >= 1 && data[0] == '{'                  ? ".gltf"
                                                                         : ".fbx";
  const std::string path = medial::fuzz::writeInput(data, size, extension);
  const medial::ImportedRig rig = medial::importRig(path);
  ::unlink(path.c_str());
  (void)rig;  // a rig or an error: both are fine, a crash or a hang is not
  return 0;
}
