// dgmf-deform --help: every option with its values and default (DGMFCommandOptions.h).
#include "DGMFCommandOptions.h"

#include "vtkDGMFDeformFilter.h"

#include <string>

namespace dgmf_cli
{
std::string Usage()
{
  std::string usage =
    "usage: dgmf-deform INPUT OUTPUT.vtu [options]\n"
    "       dgmf-deform CASE_DIR OUT_CASE_DIR --moving NAME[,NAME...] [options]\n"
    "       dgmf-deform MESH_FILE OUTPUT --moving NAME[,NAME...] [options]\n"
    "       (the options may also come before or between the files; after --, every argument\n"
    "       is a file, even one whose name starts with -)\n"
    "  INPUT                   .vtu or .vtk unstructured grid\n"
    "  MESH_FILE               a solver's mesh with boundary names: gmsh .msh, SU2 .su2,\n"
    "                          Exodus II .exo/.e/.ex2, CGNS .cgns; OUTPUT: .vtu, .vtk, or the\n"
    "                          same format (a copy of MESH_FILE with the deformed points)\n"
    "  CASE_DIR                OpenFOAM case (directory or .foam file); OUT_CASE_DIR gets the\n"
    "                          deformed points (a copy of the case if new; may be CASE_DIR)\n"
    "  --moving NAMES          moving boundaries by name (patches), comma-separated: one body "
    "each\n"
    "                          (an OpenFOAM patch group, 'wing_*' or 'flap|slat': its patches\n"
    "                          as one body; a value that is a file's name whole, commas\n"
    "                          included, is that name)\n"
    "  --static NAMES          static boundaries by name (unselected patches are static anyway)\n"
    "  --slip NAMES            planar boundaries whose nodes slide in their plane (symmetry)\n"
    "  --time T                OpenFOAM: write T/polyMesh/points (default constant)\n"
    "  --decompose-polyhedra   OpenFOAM: read polyhedra as tetrahedra and pyramids\n"
    "  --one-cell-thick MODE   detect, on or off: a one-cell-thick 2D mesh (default detect)\n"
    "  --rotate AX AY AZ       rotation angles in degrees about x, y, z (2D: AZ)\n"
    "  --center X Y Z          rotation centre (default 0 0 0); --center body: the centroid\n"
    "                          of each moving body's boundary nodes (also: --center moving)\n"
    "  --translate TX TY TZ    rigid translation (default 0 0 0)\n"
    "  --axis AX AY AZ         rotation axis through the centre (default 0 0 1), with --angle\n"
    "  --angle DEG             rotation about --axis in degrees, instead of --rotate\n"
    "motion in time (the output is then a series: OUTPUT_%04d.vtu and OUTPUT.pvd, or one time\n"
    "directory per time in an OpenFOAM case; OUTPUT may hold its own %d):\n"
    "  --rotation-law harmonic MEAN AMPLITUDE FREQUENCY PHASE\n"
    "  --rotation-law ramp START END T0 T1\n"
    "                          the angle about --axis in degrees: MEAN + AMPLITUDE\n"
    "                          sin(2 pi (FREQUENCY t + PHASE/360)), or from START to END\n"
    "  --pitch MEAN AMPLITUDE FREQUENCY PHASE   the same as --rotation-law harmonic ...\n"
    "  --translation-law harmonic|ramp P1 P2 P3 P4\n"
    "                          the distance along --translate's direction, the same forms\n"
    "  --trajectory FILE.csv   per row Time, Body, TX TY TZ, QW QX QY QZ or RX RY RZ (degrees)\n"
    "  --times START:END:COUNT the times of the series (default 0:1:21, or the table's)\n"
    "  --marker NAME           boundary-marker point array (default "
    "BoundaryMarker if present)\n"
    "  --displacement NAME     displacement point array (default Displacement "
    "if present)\n"
    "  --body-id NAME          body-id point array: 0 off the bodies, 1, 2, ... each body\n"
    "                          (several bodies: Documentation/bodies.md; default none)\n";
  usage +=
    "  --method NAME           " + vtkDGMFDeformFilter::GetMethodKeys(", ") + " (default dgmf)\n";
  usage +=
    "  --mode 1|2              DGMF1 or DGMF2 (default 2)\n"
    "  --damping 1..7          damping function u1..u7 (default 1)\n"
    "  --r0s VALUE             static-boundary r0, >= 1 (default 1)\n"
    "  --sub-steps N           large motions: N sub-steps (at most 1000), 0 = automatic "
    "(default 1)\n"
    "  --repair T              quality guard: repair cells with SizeSkew below T (default 0: "
    "off)\n"
    "  --repair-layers N       layers around bad cells whose interior nodes may move, 0 to "
    "100 (default 2)\n"
    "  --repair-passes N       most repair passes per step, 0 to 10000 (default 20)\n"
    "  --threads N             number of threads, 0 = all (default 0)\n"
    "  --no-quality            skip the SizeSkew quality metric\n"
    "  --fail-on-inverted      exit with code 3, writing nothing, if a cell is inverted\n"
    "  --progress              show the progress from the start (default: after 2 s)\n"
    "  --no-write              read and deform only, write nothing (see where the time goes)\n"
    "  --vtu-mode MODE         appended (raw, default: fast; ParaView on Debian 12 needs the\n"
    "                          expat work-around, dgmf-paraview) or binary (inline base64:\n"
    "                          what stock ParaView on Debian 12 reads)\n"
    "  --compression NAME      .vtu compression: none (default in appended mode: the fastest\n"
    "                          write), lz4 (default inline: files ~0.6 times as large), zlib\n"
    "                          or lzma (meshio 5 reads zlib best)\n"
    "  --non-orthogonality     report the maximum face non-orthogonality as checkMesh does\n"
    "                          (on for OpenFOAM cases; of VTK's pieces with\n"
    "                          --decompose-polyhedra, which checkMesh does not see)\n"
    "exit codes: 0 written; 1 could not read, deform or write; 2 bad option; 3 inverted cells\n"
    "            with --fail-on-inverted (nothing written)\n";
  return usage;
}
} // namespace dgmf_cli
