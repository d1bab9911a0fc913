/**
 * @file ResultNames.h
 * @brief The names of everything a deformation or a quality evaluation adds to its output: one
 * list for the core's reports, the VTK filters, the command line and the tests.
 * Documentation/properties.md describes each one.
 */
#ifndef dgmf_ResultNames_h
#define dgmf_ResultNames_h

namespace dgmf
{
namespace names
{
// Point arrays (DGMF).
constexpr const char* R = "r"; ///< interpolated boundary value r (one body)
constexpr const char* F = "f"; ///< damping factor f

// Cell arrays (the quality metric).
constexpr const char* SizeSkew = "SizeSkew"; ///< Knupp's size-skew relative to the input cell
constexpr const char* Inverted = "Inverted"; ///< 1 for a cell the deformation inverted
/// 1 for a cell non-convex, inverted or degenerate in the input (judged through its faces)
constexpr const char* InputInvalid = "InputInvalid";
/// degrees: the largest face non-orthogonality of the cell (OpenFOAM's checkMesh definition)
constexpr const char* NonOrthogonality = "NonOrthogonality";

// Field data: the quality summary.
constexpr const char* SizeSkewMean = "SizeSkewMean";
constexpr const char* SizeSkewMinimum = "SizeSkewMinimum";
constexpr const char* InvertedCellCount = "InvertedCellCount";
constexpr const char* SizeSkewEvaluatedCells = "SizeSkewEvaluatedCells";
constexpr const char* InputInvalidCellCount = "InputInvalidCellCount";
constexpr const char* MaximumNonOrthogonality = "MaximumNonOrthogonality";           ///< degrees
constexpr const char* InputMaximumNonOrthogonality = "InputMaximumNonOrthogonality"; ///< degrees

// Field data: every method.
constexpr const char* Method = "Method";         ///< the method's name (MethodTable.def)
constexpr const char* MotionTime = "MotionTime"; ///< the time of a motion that depends on time

// Field data: the graph methods (DGMF, DGM, DGRBF).
constexpr const char* OutsideNodeCount = "OutsideNodeCount";
constexpr const char* GraphReused = "GraphReused";
constexpr const char* InvertedGraphElementCount = "InvertedGraphElementCount"; ///< DGM

// Field data: RBF and IDW.
constexpr const char* RBFCentreCount = "RBFCentreCount";
constexpr const char* RBFBoundaryError = "RBFBoundaryError";
constexpr const char* IDWReferenceLength = "IDWReferenceLength";

// Field data: DGMF's extracted rigid motions (one tuple per body).
constexpr const char* FittedTranslation = "FittedTranslation";
constexpr const char* FittedRotationCenter = "FittedRotationCenter";
constexpr const char* FittedRotationAxis = "FittedRotationAxis";
constexpr const char* FittedRotationAngle = "FittedRotationAngle";
constexpr const char* FittedResidualRMS = "FittedResidualRMS";

// Field data: DGMF's sub-steps and quality guard.
constexpr const char* SubStepsUsed = "SubStepsUsed";
constexpr const char* RejectedSubSteps = "RejectedSubSteps";
constexpr const char* RepairedCellCount = "RepairedCellCount";
constexpr const char* UnrepairedCellCount = "UnrepairedCellCount";

// Field data of a mesh file's multiblock (vtkDGMFMeshFileReader), which the filter reads: the
// file's named groups that are not boundaries (a gmsh physical curve of a 3D mesh, a volume
// group) and their dimensions, so that such a name given as a boundary is said to be one.
constexpr const char* NonBoundaryGroups = "NonBoundaryGroups";
constexpr const char* NonBoundaryGroupDimensions = "NonBoundaryGroupDimensions";
// ... and on a boundary block, the file's group of boundaries it is in (a CGNS family): the
// group's name chooses all its blocks.
constexpr const char* BoundaryFamily = "BoundaryFamily";
} // namespace names
} // namespace dgmf

#endif
