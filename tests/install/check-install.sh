#!/usr/bin/env bash
# Installs Medial the two ways a user would and runs it from there, with nothing of the build tree in
# reach: no PYTHONPATH, no LD_LIBRARY_PATH, and programs whose RUNPATH names no build folder.
#   check-install.sh prefix BUILD_DIR SCRATCH   cmake --install into SCRATCH/prefix, then moved elsewhere
#   check-install.sh deb BUILD_DIR SCRATCH      cpack's .deb: its Depends and files, then its extracted tree
set -euo pipefail
mode=$1 build=$(cd "$2" && pwd) scratch=$3
rm -rf "$scratch" && mkdir -p "$scratch"
fail() { echo "check-install: $*" >&2; exit 1; }

# Runs the installed tree at $1 (a prefix): version, a skeleton and a centerline of bundled samples, Python.
run_tree() {
  local prefix=$1
  for program in medial medial-make-colon-phantom; do
    [ -x "$prefix/bin/$program" ] || fail "$prefix/bin/$program is missing"
    if readelf -d "$prefix/bin/$program" | grep -E 'R(UN)?PATH' | grep -q "$build"; then
      fail "$program's RUNPATH names the build folder"
    fi
  done
  env -i PATH=/usr/bin:/bin HOME="$scratch" "$prefix/bin/medial" --version | grep -q "^medial " ||
    fail "medial --version"
  env -i PATH=/usr/bin:/bin HOME="$scratch" "$prefix/bin/medial" skeleton \
    "$prefix/share/medial/samples/meshes/torus.off" -o "$scratch/torus-skeleton.vtp" --quiet ||
    fail "medial skeleton on the installed sample"
  [ -s "$scratch/torus-skeleton.vtp" ] || fail "no skeleton written"
  env -i PATH=/usr/bin:/bin HOME="$scratch" "$prefix/bin/medial" centerline \
    "$prefix/share/medial/samples/volumes/tubes/helix.nii.gz" -o "$scratch/helix-centerline.vtp" --quiet ||
    fail "medial centerline on the installed sample volume (ITK's reader, a plugin of libMedialFilters)"
  env -i PATH=/usr/bin:/bin HOME="$scratch" PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 -c "
import vtk, medial
sphere = vtk.vtkSphereSource()
topology = medial.vtkMedialMeshTopology()
topology.SetInputConnection(sphere.GetOutputPort())
topology.Update()
assert topology.GetClosedManifold() and topology.GetGenus() == 0
assert medial.__file__.startswith('$prefix'), medial.__file__
print('import medial', medial.__version__, 'from', medial.__file__)
" || fail "import medial from $prefix"
}

case $mode in
  prefix)
    cmake --install "$build" --prefix "$scratch/prefix" >/dev/null
    for f in include/medial/vtkMedialSQM.h include/medial/sqm/SqmMesher.h lib/cmake/medial/MedialConfig.cmake \
             lib/python3/dist-packages/medial/__init__.py share/applications/medial-gui.desktop \
             share/blender/scripts/addons/medial_blender/__init__.py; do
      [ -e "$scratch/prefix/$f" ] || fail "$f is not installed"
    done
    mv "$scratch/prefix" "$scratch/moved"  # relative RUNPATHs: the tree runs from anywhere
    run_tree "$scratch/moved"
    ;;
  deb)
    (cd "$build" && cpack --config CPackConfig.cmake -B "$scratch/package" >/dev/null)
    deb=$(ls "$scratch"/package/medial_*_amd64.deb)
    info=$(dpkg-deb -I "$deb")
    for dependency in libvtk9.1 libqt6widgets6 python3-vtk9 xvfb libopenmesh; do
      echo "$info" | grep -q "Depends:.*$dependency" || fail "Depends lacks $dependency: $(echo "$info" | grep Depends)"
    done
    contents=$(dpkg-deb -c "$deb")
    for f in ./usr/bin/medial ./usr/bin/medial-gui ./usr/lib/libMedialFilters.so ./usr/lib/libMedialITKIO.so \
             ./usr/lib/python3/dist-packages/medial/__init__.py ./usr/share/applications/medial-gui.desktop \
             ./usr/share/icons/hicolor/scalable/apps/medial.svg ./usr/share/man/man1/medial.1 \
             ./usr/share/man/man1/medial-skeleton.1 ./usr/share/man/man1/medial-gui.1 \
             ./usr/share/blender/scripts/addons/medial_blender/__init__.py \
             ./usr/share/blender/scripts/addons/medial_blender/operators.py; do
      echo "$contents" | grep -q " $f\$" || fail "the package lacks $f"
    done
    dpkg-deb -x "$deb" "$scratch/root"
    run_tree "$scratch/root/usr"
    if command -v blender >/dev/null; then  # the installed add-on folder, as Blender's add-on search sees it
      BLENDER_USER_SCRIPTS="$scratch/root/usr/share/blender/scripts" blender -b --factory-startup --python-exit-code 1 \
        --python-expr "import addon_utils, bpy
assert addon_utils.enable('medial_blender', default_set=True) is not None
assert hasattr(bpy.types, 'MEDIAL_OT_rig_mesh') and hasattr(bpy.types, 'MEDIAL_PT_panel')" \
        >"$scratch/blender.log" 2>&1 || fail "Blender cannot enable the packaged add-on: $(tail -5 "$scratch/blender.log")"
    fi
    echo "check-install: $(basename "$deb"), $(echo "$contents" | wc -l) entries, $(echo "$info" | grep Depends)"
    ;;
  *) fail "mode is prefix or deb" ;;
esac
echo "check-install: $mode ok"
