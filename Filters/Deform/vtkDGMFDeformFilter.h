/**
 * @class   vtkDGMFDeformFilter
 * @brief   Deforms a volume (3D) or planar (2D) mesh when its boundary moves, by Delaunay graph
 *          mapping with damping functions (DGMF).
 *
 * vtkDGMFDeformFilter takes a vtkUnstructuredGrid whose boundary nodes carry a prescribed motion
 * and moves every other node so that the mesh follows (Wang, Qin, Zhao, Chinese Journal of
 * Aeronautics 31(11), 2018): every node is located in an element of the Delaunay graph of the
 * boundary nodes (built with CGAL), its relative distance r and damping factor f = u(r) are
 * interpolated from the boundary, and it moves by f times the rigid motion (Translation,
 * RotationAngles about RotationCenter) plus the interpolated shape deformation d
 * (Documentation/architecture.md numbers the paper's seven steps).
 *
 * The shape deformation d comes from the displacement point array (input array 0, 3 components):
 * in DGMF2 mode (default) it is given at the moving boundary nodes and interpolated inside each
 * graph element (paper Eq. 7); in DGMF1 mode every node's own value is used.
 *
 * Which nodes are boundary nodes, and which of them move, comes from the boundary blocks named
 * (AddMovingBoundary, AddStaticBoundary, AddSlipBoundary: composite input), else from the
 * optional boundary-marker point array (input array 1, 1 component, values 0 to 3; integer or
 * floating-point): 0 = interior, 1 = static boundary, 2 = moving boundary, 3 = slip boundary (the
 * node moves within the plane of the slip nodes). Without either, the boundary nodes are the nodes
 * of the mesh's boundary faces (3D) or edges (2D), and a boundary node is moving where its
 * displacement is non-zero.
 *
 * Composite input (vtkMultiBlockDataSet, vtkPartitionedDataSetCollection, as the CGNS, Exodus and
 * OpenFOAM readers produce) is deformed as one mesh with one graph: the blocks with explicit
 * points (volume blocks and boundary patches) are merged at their coincident nodes, deformed
 * together, and the output has the input's block structure, each block with its own arrays plus
 * the filter's (SizeSkew for its own cells); the quality summary is in the output's field data.
 * The output has the input's type (vtkPassInputTypeAlgorithm); GetOutput() returns it for
 * unstructured-grid input, GetOutputDataObject(0) for any.
 *
 * A mesh is 2D when it has no 3D cell and all its nodes have the same z (up to 1e-6 of its x-y
 * extent: round-off; each node keeps its own z); the graph is then 2D and
 * the mesh can only rotate about z. Otherwise the graph is 3D.
 *
 * Output: the deformed grid, with every input point, cell and field array passed through, plus
 * - point arrays `r` and `f`;
 * - cell arrays `SizeSkew` (Knupp's size-skew metric relative to the same input cell; polyhedra,
 *   polygons and cells non-convex in the input through their faces; NaN for quadratic cells),
 *   `Inverted` (1 for a cell the deformation inverted) and `InputInvalid` (1 for a cell already
 *   non-convex, inverted or degenerate in the input), when ComputeQuality is on;
 * - field data `SizeSkewMean`, `SizeSkewMinimum`, `InvertedCellCount` (cells made invalid by the
 *   deformation), `InputInvalidCellCount`, `OutsideNodeCount`;
 * - with ComputeNonOrthogonality: the cell array `NonOrthogonality` and the field data
 *   `MaximumNonOrthogonality` and `InputMaximumNonOrthogonality` (degrees, as checkMesh).
 * Output points are always double precision. The input is never modified.
 *
 * Motion in time (RotationLaw, TranslationLaw, or a trajectory table on input port 1): the filter
 * reports time steps and deforms the input mesh for the time requested (no drift), reusing the
 * graph; the output's field data MotionTime has the time of its motion.
 *
 * The Delaunay graph and the node locations are kept between executions while the input's
 * points, cells and boundary classification are unchanged: changing only the motion, the
 * damping function or the displacement values re-runs only the cheap per-node pass.
 *
 * Method selects the deformation method: DGMF (default) or one of the methods the paper compares
 * against, with the same inputs and outputs so that methods can be compared on the same mesh:
 * DGM (Delaunay graph mapping), DGRBF (a local RBF per graph element), RBF (global RBF
 * interpolation with a linear polynomial, optionally with greedy centre selection) and IDW
 * (inverse distance weighting, Luke et al. 2012). These four interpolate the total motion of the
 * boundary nodes (rigid part plus displacement). The point arrays r and f exist for DGMF only.
 * Method-specific field data: InvertedGraphElementCount (DGM), RBFCentreCount and
 * RBFBoundaryError (RBF), IDWReferenceLength (IDW); every method writes the string Method.
 *
 * @warning Threaded with vtkSMPTools (see NumberOfThreads). Results are identical for any number
 * of threads.
 *
 * Documentation/architecture.md draws the steps of a run, file by file.
 *
 * @sa vtkWarpVector vtkTransformFilter vtkSizeSkewQualityFilter
 */
#ifndef vtkDGMFDeformFilter_h
#define vtkDGMFDeformFilter_h

#include "DGMFFiltersModule.h" // for export macro
#include "vtkPassInputTypeAlgorithm.h"

class vtkAlgorithmOutput;
class vtkMultiProcessController;
class vtkTable;
class vtkUnstructuredGrid;
namespace dgmf_vtk
{
class CompositeMesh;
}

#include <cstddef> // for std::size_t
#include <memory>  // for std::unique_ptr
#include <string>  // for std::string

class DGMFFILTERS_EXPORT vtkDGMFDeformFilter : public vtkPassInputTypeAlgorithm
{
public:
  static vtkDGMFDeformFilter* New();
  vtkTypeMacro(vtkDGMFDeformFilter, vtkPassInputTypeAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The output for unstructured-grid input (null for composite input: use
   * GetOutputDataObject(0)).
   */
  vtkUnstructuredGrid* GetOutput();
  vtkUnstructuredGrid* GetOutput(int port);
  ///@}

  /// Damping functions of the paper's Table 1.
  enum DampingFunctions
  {
    U1 = 1, ///< (1-r)^2 (r+1), the paper's choice
    U2 = 2, ///< (1-r)^4 (4r+1), Wendland C2
    U3 = 3, ///< (1-r)^6 (35r^2+18r+3)/3, Wendland C4
    U4 = 4, ///< (1-r)^8 (32r^3+25r^2+8r+1), Wendland C6
    U5 = 5, ///< (1-r)^3 (r+1)
    U6 = 6, ///< (1-r)^2
    U7 = 7  ///< 1-r
  };

  /// Where the shape deformation of the interior nodes comes from.
  enum DeformationModes
  {
    DGMF1 = 1, ///< the displacement array is given at every node
    DGMF2 = 2  ///< given at the moving boundary nodes, interpolated by paper Eq. 7
  };

  /// Deformation methods: the values of the method table (Filters/DGMFCore/dgmf/MethodTable.def,
  /// which also names and describes them).
  enum Methods
  {
    DGMF = 0,
    DGM = 1,
    DGRBF = 2,
    RBF = 3,
    IDW = 4
  };

  ///@{
  /**
   * The method table (Filters/DGMFCore/dgmf/MethodTable.def), for programs that name methods:
   * the name of a method ("DGMF"; null for an unknown value), its command-line key ("dgmf"), the
   * method of a name or key in any case (-1 if none), and the keys of all methods separated by
   * `separator`.
   */
  static const char* GetMethodName(int method);
  static const char* GetMethodKey(int method);
  static int GetMethodFromName(const char* name);
  static std::string GetMethodKeys(const char* separator);
  ///@}

  ///@{
  /**
   * The deformation method, one of Methods. Default: DGMF.
   */
  vtkSetClampMacro(Method, int, DGMF, IDW);
  vtkGetMacro(Method, int);
  void SetMethodToDGMF() { this->SetMethod(DGMF); }
  void SetMethodToDGM() { this->SetMethod(DGM); }
  void SetMethodToDGRBF() { this->SetMethod(DGRBF); }
  void SetMethodToRBF() { this->SetMethod(RBF); }
  void SetMethodToIDW() { this->SetMethod(IDW); }
  ///@}

  ///@{
  /**
   * Damping function u(r) of DGMF, one of DampingFunctions. Default: U1.
   */
  vtkSetClampMacro(DampingFunction, int, U1, U7);
  vtkGetMacro(DampingFunction, int);
  void SetDampingFunctionToU1() { this->SetDampingFunction(U1); }
  void SetDampingFunctionToU2() { this->SetDampingFunction(U2); }
  ///@}

  ///@{
  /**
   * r0s, the value of r on the static boundary (>= 1). Larger values shrink the region that
   * follows the moving body. Default: 1.
   */
  vtkSetClampMacro(StaticBoundaryR0, double, 1.0, VTK_DOUBLE_MAX);
  vtkGetMacro(StaticBoundaryR0, double);
  ///@}

  ///@{
  /**
   * Rigid translation t of the moving boundary, in mesh units. Default: (0, 0, 0).
   */
  vtkSetVector3Macro(Translation, double);
  vtkGetVector3Macro(Translation, double);
  ///@}

  ///@{
  /**
   * Centre c of the rigid rotation, used when RotationCenterMode is GIVEN. Default: (0, 0, 0).
   */
  vtkSetVector3Macro(RotationCenter, double);
  vtkGetVector3Macro(RotationCenter, double);
  ///@}

  /// Where the centre of the rigid rotation is.
  enum RotationCenterModes
  {
    GIVEN = 0,        ///< RotationCenter
    BODY_CENTROID = 1 ///< the centroid of the moving body's boundary nodes (each body's own)
  };

  ///@{
  /**
   * Where the rotation centre is: RotationCenter (GIVEN), or the centroid of the moving body's
   * boundary nodes (BODY_CENTROID: each body its own; a body given SetBodyMotion keeps its centre).
   * Default: GIVEN.
   */
  vtkSetClampMacro(RotationCenterMode, int, GIVEN, BODY_CENTROID);
  vtkGetMacro(RotationCenterMode, int);
  ///@}

  ///@{
  /**
   * Rigid rotation angles, in degrees, about the x, y and z axes through RotationCenter,
   * right-handed, applied in the order x, y, z. A 2D mesh accepts only the angle about z.
   * Default: (0, 0, 0).
   */
  vtkSetVector3Macro(RotationAngles, double);
  vtkGetVector3Macro(RotationAngles, double);
  ///@}

  ///@{
  /**
   * Rotation about an axis: RotationAngle degrees, right-handed, about the line through
   * RotationCenter along RotationAxis (any length; 2D meshes: (0, 0, +-1)), instead of
   * RotationAngles (both non-zero: an error). Defaults: RotationAxis (0, 0, 1), RotationAngle 0.
   */
  vtkSetVector3Macro(RotationAxis, double);
  vtkGetVector3Macro(RotationAxis, double);
  vtkSetMacro(RotationAngle, double);
  vtkGetMacro(RotationAngle, double);
  ///@}

  /// Laws in time of the rotation angle and of the translation (dgmf::MotionLawKind's values).
  enum MotionLaws
  {
    CONSTANT = 0, ///< the motion as the properties give it, at every time
    HARMONIC = 1, ///< mean + amplitude sin(2 pi (frequency t + phase / 360))
    RAMP = 2      ///< from a start value to an end value between a start time and an end time
  };

  ///@{
  /**
   * The rotation angle in time, one of MotionLaws: with HARMONIC or RAMP, the law's value in
   * degrees about RotationAxis (RotationAngle unused; RotationAngles must be 0 0 0). Parameters:
   * HARMONIC mean, amplitude (degrees), frequency (periods per unit time), phase (degrees); RAMP
   * start and end angles, start and end times. Times a period apart give the same bits
   * (dgmf::MotionLaw). A law that can reach beyond +-720 degrees is an error at every time.
   * Defaults: CONSTANT, (0, 10, 1, 0).
   */
  vtkSetClampMacro(RotationLaw, int, CONSTANT, RAMP);
  vtkGetMacro(RotationLaw, int);
  vtkSetVector4Macro(RotationLawParameters, double);
  vtkGetVector4Macro(RotationLawParameters, double);
  ///@}

  ///@{
  /**
   * The translation in time, one of MotionLaws: with HARMONIC or RAMP, the law's value (a
   * distance) along Translation's direction (Translation must not be zero); parameters as the
   * rotation law's, in mesh units. Defaults: CONSTANT, (0, 1, 1, 0).
   */
  vtkSetClampMacro(TranslationLaw, int, CONSTANT, RAMP);
  vtkGetMacro(TranslationLaw, int);
  vtkSetVector4Macro(TranslationLawParameters, double);
  vtkGetVector4Macro(TranslationLawParameters, double);
  ///@}

  ///@{
  /**
   * The time steps reported when the motion depends on time (a law, or a trajectory table) and
   * the input has fewer than two (an OpenFOAM case's "0" alone): NumberOfTimeSteps times spread
   * over TimeRange, both ends included, in increasing order (a range given end first is taken from
   * its low end; an empty range is one time). With a table: the table's times. Defaults: (0, 1)
   * and 21.
   */
  vtkSetVector2Macro(TimeRange, double);
  vtkGetVector2Macro(TimeRange, double);
  vtkSetClampMacro(NumberOfTimeSteps, int, 1, 1000000);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  ///@{
  /**
   * The optional trajectory table (input port 1, e.g. ParaView's CSV reader): columns Time, Body
   * (default 1), TX TY TZ, and QW QX QY QZ (unit quaternion) or RX RY RZ (degrees); interpolated
   * linearly and by slerp, about RotationCenter. Its bodies take their motion from it. Bad tables
   * are errors naming the row or column (Documentation/motion.md). Default: none.
   */
  void SetTrajectoryConnection(vtkAlgorithmOutput* output);
  void SetTrajectoryData(vtkTable* table);
  ///@}

  /// The time of the last execution's motion (0 when the motion does not depend on time).
  double GetLastMotionTime() const;

  /// Where DGMF's rigid motion comes from.
  enum RigidMotionModes
  {
    PROPERTIES = 0, ///< Translation, RotationCenter, RotationAngles (or SetBodyMotion per body)
    EXTRACTED =
      1 ///< fitted to each body's displacements (Kabsch); the residual is the shape deformation
  };

  ///@{
  /**
   * DGMF's rigid motion, one of RigidMotionModes. EXTRACTED fits, to each moving body's nodes,
   * the best rigid motion (least squares, centre = the body's centroid) to the displacement array,
   * which is then the *total* displacement of the moving nodes; the residual is the shape
   * deformation (DGMF2). The fits are reported in the field data (FittedTranslation,
   * FittedRotationCenter, FittedRotationAxis, FittedRotationAngle, FittedResidualRMS, one tuple per
   * body). The other methods interpolate the displacement array as the total motion either way.
   * Default: PROPERTIES.
   */
  vtkSetClampMacro(RigidMotionMode, int, PROPERTIES, EXTRACTED);
  vtkGetMacro(RigidMotionMode, int);
  void SetRigidMotionModeToProperties() { this->SetRigidMotionMode(PROPERTIES); }
  void SetRigidMotionModeToExtracted() { this->SetRigidMotionMode(EXTRACTED); }
  ///@}

  ///@{
  /**
   * The rigid motion of moving body `bodyId` (>= 1, see SetBodyIdArrayName) in PROPERTIES mode:
   * translation, rotation centre and angles about x, y, z (degrees). Bodies without one use
   * Translation, RotationCenter and RotationAngles. RemoveAllBodyMotions() forgets them. (The id
   * is a double so that ParaView's repeated DoubleVectorProperty can call this; it must be a
   * whole number >= 1.)
   */
  void SetBodyMotion(double bodyId, double tx, double ty, double tz, double cx, double cy,
    double cz, double ax, double ay, double az);
  void RemoveAllBodyMotions();
  ///@}

  ///@{
  /**
   * DGMF1 or DGMF2 (see DeformationModes). Default: DGMF2.
   */
  vtkSetClampMacro(DeformationMode, int, DGMF1, DGMF2);
  vtkGetMacro(DeformationMode, int);
  void SetDeformationModeToDGMF1() { this->SetDeformationMode(DGMF1); }
  void SetDeformationModeToDGMF2() { this->SetDeformationMode(DGMF2); }
  ///@}

  ///@{
  /**
   * Support radius R of the Wendland C2 basis of RBF and DGRBF, in mesh units; 0 = automatic.
   * RBF: automatic is the diagonal of the boundary nodes' bounding box; a smaller radius gives a
   * sparse system. DGRBF: R is at least each element's longest edge; automatic is twice it.
   * Default: 0.
   */
  vtkSetClampMacro(SupportRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SupportRadius, double);
  ///@}

  ///@{
  /**
   * RBF greedy centre selection (Rendall and Allen 2009): centres are added until the error at
   * every boundary node is below RBFGreedyTolerance times the largest boundary displacement, or
   * RBFGreedyMaximumPoints centres are used (at least the dimension + 1: 3 in 2D, 4 in 3D; fewer
   * is an error). Defaults: off, 1e-3, 2000.
   */
  vtkSetMacro(RBFGreedy, bool);
  vtkGetMacro(RBFGreedy, bool);
  vtkBooleanMacro(RBFGreedy, bool);
  vtkSetClampMacro(RBFGreedyTolerance, double, 0.0, 1.0);
  vtkGetMacro(RBFGreedyTolerance, double);
  vtkSetClampMacro(RBFGreedyMaximumPoints, int, 3, VTK_INT_MAX);
  vtkGetMacro(RBFGreedyMaximumPoints, int);
  ///@}

  ///@{
  /**
   * IDW weights w = A [(L/d)^3 + (alpha L/d)^5]: alpha (default 5) and the reference length L
   * in mesh units (default 0 = automatic: the largest distance of a boundary node from the
   * boundary nodes' centroid).
   */
  vtkSetClampMacro(IDWAlpha, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(IDWAlpha, double);
  vtkSetClampMacro(IDWReferenceLength, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(IDWReferenceLength, double);
  ///@}

  ///@{
  /**
   * Large motions (DGMF, one body given by the properties): the motion is split into SubSteps
   * steps along the moving nodes' path (the rotation about its axis, the translation and the
   * displacement in equal parts); the Delaunay graph is rebuilt on the current mesh before each
   * step. 0 = automatic: the first step tries the whole motion; a step whose mesh (repaired, when
   * the guard is on) still has an inverted cell or a SizeSkew below RepairThreshold is halved
   * (down to 1/64 of the motion) while halving reduces the bad cells; after a clean step the next
   * tries twice as far. Default: 1 (the paper's single step). See Documentation/large_motions.md.
   */
  vtkSetClampMacro(SubSteps, int, 0, 1000);
  vtkGetMacro(SubSteps, int);
  ///@}

  ///@{
  /**
   * The quality guard: after each step, the cells whose SizeSkew (relative to the input cell) is
   * below RepairThreshold, and every inverted cell, are repaired by moving nearby interior nodes
   * (untangling and optimisation-based smoothing, Documentation/repair.md); boundary nodes never
   * move. 0 turns the guard off. RepairLayers: node-neighbour layers around the bad cells whose
   * interior nodes may move; RepairPasses: most passes. Defaults: 0 (off), 2, 20.
   */
  vtkSetClampMacro(RepairThreshold, double, 0.0, 1.0);
  vtkGetMacro(RepairThreshold, double);
  vtkSetClampMacro(RepairLayers, int, 0, 100);
  vtkGetMacro(RepairLayers, int);
  vtkSetClampMacro(RepairPasses, int, 0, 10000);
  vtkGetMacro(RepairPasses, int);
  ///@}

  ///@{
  /**
   * Compute the cell arrays SizeSkew, Inverted, InputInvalid and the quality summary. Default: on.
   */
  vtkSetMacro(ComputeQuality, bool);
  vtkGetMacro(ComputeQuality, bool);
  vtkBooleanMacro(ComputeQuality, bool);
  ///@}

  ///@{
  /**
   * Compute the face non-orthogonality of the 3D cells as OpenFOAM's checkMesh defines it (the
   * angle between the line joining two cell centres and their face's area vector): the cell array
   * NonOrthogonality (degrees, the largest over the cell's internal faces) and the field data
   * MaximumNonOrthogonality and InputMaximumNonOrthogonality. The internal faces are kept while the
   * cells are unchanged. Default: off (it costs about as much as the deformation).
   */
  vtkSetMacro(ComputeNonOrthogonality, bool);
  vtkGetMacro(ComputeNonOrthogonality, bool);
  vtkBooleanMacro(ComputeNonOrthogonality, bool);
  ///@}

  ///@{
  /**
   * Fail (error message, empty output) when the deformed mesh has an inverted cell, instead of
   * producing it with the cells flagged in the Inverted array. Needs ComputeQuality (on without it
   * is an error). Default: off.
   */
  vtkSetMacro(FailOnInvertedCells, bool);
  vtkGetMacro(FailOnInvertedCells, bool);
  vtkBooleanMacro(FailOnInvertedCells, bool);
  ///@}

  ///@{
  /**
   * Number of threads; 0 uses all hardware threads (and the STDThread vtkSMPTools backend when
   * the active backend is Sequential). Default: 0.
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * Boundaries chosen by name, for composite input (the OpenFOAM reader's patches, Exodus side
   * sets, any named block): a block name ("wing"; OpenFOAM region names such as "patch/wing" work
   * too) or a selector of the input's hierarchy ("/Root/boundary/wing", as ParaView's block tree
   * gives them); an entry may name several blocks as one boundary, "wing_*" (shell wildcards) or
   * "flap|slat" (alternatives, each naming a block: an OpenFOAM patch group is one of these for
   * dgmf-deform); a name no block has names the blocks of that family (field data BoundaryFamily,
   * a CGNS FamilyName). Each moving entry is one body (body 1, 2, ... in order: with several, each
   * has its own damping field and motion, SetBodyMotion); static entries stay; the nodes of a slip
   * entry (a plane: a symmetry plane) move only within it. The boundary blocks not named (blocks of
   * lower dimension than the mesh), and the nodes of the mesh's own boundary that no block holds
   * (a reader asked for the moving patch only), are static, but for the two planes of a
   * one-cell-thick mesh. A node in several blocks is moving if one of them moves (the first body
   * listed wins), else static if one is static, else slip; a node on two slip planes of a 3D mesh
   * slides along their line, on three (or on two lines of a 2D mesh) it is static.
   * With names, the boundary-marker and body-id arrays are not read; an unknown name is an error
   * that lists the input's block names. Default: none (the marker or the mesh's boundary decide).
   */
  void AddMovingBoundary(const char* name);
  void RemoveAllMovingBoundaries();
  void AddStaticBoundary(const char* name);
  void RemoveAllStaticBoundaries();
  void AddSlipBoundary(const char* name);
  void RemoveAllSlipBoundaries();
  ///@}

  /// How a one-cell-thick mesh (all nodes on two planes normal to x, y or z, in pairs) is deformed.
  enum OneCellThickModes
  {
    DETECT = 0, ///< as a 2D mesh when it is one cell thick (default)
    OFF = 1,    ///< always as a 3D mesh
    ON = 2      ///< as a 2D mesh; an error when it is not one cell thick
  };

  ///@{
  /**
   * One-cell-thick 2D meshes (OpenFOAM's 2D cases, between two `empty` patches): deformed as the
   * 2D mesh of one layer, whose in-plane motion both layers take bit for bit; the coordinate
   * across the layers is kept. The two planes are not boundaries (without names or a marker, the
   * boundary is the faces across them). The motion must stay in the plane (a rotation about the
   * axis across the layers). Distributed runs deform it as 3D: its two planes must be slip
   * boundaries (DETECT says so). Default: DETECT.
   */
  vtkSetClampMacro(OneCellThickMode, int, DETECT, ON);
  vtkGetMacro(OneCellThickMode, int);
  ///@}

  ///@{
  /**
   * Convenience for SetInputArrayToProcess: the point array with the shape-deformation
   * displacement (index 0), the boundary-marker point array (index 1) and the body-id point array
   * (index 2: 0 = not on a moving body, 1, 2, ... = the moving body; DGMF only: each body gets its
   * own damping field and rigid motion, and the bodies' displacements are summed). "None": no
   * array; null: the default again. Defaults, when never set: the input's point array
   * `Displacement` (3 components) and `BoundaryMarker` (1 component) when it has them, else none.
   */
  void SetDisplacementArrayName(const char* name);
  void SetBoundaryMarkerArrayName(const char* name);
  void SetBodyIdArrayName(const char* name);
  ///@}

  ///@{
  /**
   * The controller of a distributed run (pvbatch, pvserver under MPI): every process holds a
   * piece of the mesh; the boundary nodes of all pieces are exchanged, every process builds the
   * same Delaunay graph and deforms its own nodes, and the quality summary covers all pieces.
   * Default: the global controller (none, or one process, in a serial run).
   */
  virtual void SetController(vtkMultiProcessController* controller);
  vtkGetObjectMacro(Controller, vtkMultiProcessController);
  ///@}

  /// True when the last execution reused the cached Delaunay graph and node locations.
  bool GetLastExecutionReusedGraph() const { return this->LastExecutionReusedGraph; }

  ///@{
  /**
   * Wall-clock seconds of the phases of the last execution: building the Delaunay graph, locating
   * the nodes (both 0 when the cache was reused), the deformation itself (r, f and the new
   * positions, or the method's fit and evaluation), and the quality metrics (SizeSkew and, when on,
   * the non-orthogonality; 0 when both are off).
   */
  double GetLastGraphSeconds() const { return this->LastGraphSeconds; }
  double GetLastLocationSeconds() const { return this->LastLocationSeconds; }
  double GetLastDeformationSeconds() const { return this->LastDeformationSeconds; }
  double GetLastQualitySeconds() const { return this->LastQualitySeconds; }
  ///@}

  ///@{
  /**
   * The mesh the last execution deformed: its nodes and cells. For a composite input, the merged
   * mesh: points shared by blocks counted once, and the volume cells (the output's blocks count
   * every block's points and cells). 0 before an execution and after one that failed.
   */
  vtkIdType GetLastNumberOfNodes() const { return this->LastNumberOfNodes; }
  vtkIdType GetLastNumberOfCells() const { return this->LastNumberOfCells; }
  ///@}

  /// Memory kept between executions (graph, node locations, r), in bytes.
  std::size_t GetCacheMemorySize() const;

  /// Drops the cached graph and node locations (the next execution rebuilds them).
  void ReleaseCache();

protected:
  vtkDGMFDeformFilter();
  ~vtkDGMFDeformFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Method = DGMF;
  int DampingFunction = U1;
  double StaticBoundaryR0 = 1.0;
  double Translation[3] = { 0.0, 0.0, 0.0 };
  double RotationCenter[3] = { 0.0, 0.0, 0.0 };
  double RotationAngles[3] = { 0.0, 0.0, 0.0 };
  double RotationAxis[3] = { 0.0, 0.0, 1.0 };
  double RotationAngle = 0.0;
  int RotationLaw = CONSTANT;
  double RotationLawParameters[4] = { 0.0, 10.0, 1.0, 0.0 };
  int TranslationLaw = CONSTANT;
  double TranslationLawParameters[4] = { 0.0, 1.0, 1.0, 0.0 };
  double TimeRange[2] = { 0.0, 1.0 };
  int NumberOfTimeSteps = 21;
  int DeformationMode = DGMF2;
  int RigidMotionMode = PROPERTIES;
  double SupportRadius = 0.0;
  bool RBFGreedy = false;
  double RBFGreedyTolerance = 1e-3;
  int RBFGreedyMaximumPoints = 2000;
  double IDWAlpha = 5.0;
  double IDWReferenceLength = 0.0;
  int SubSteps = 1;
  double RepairThreshold = 0.0;
  int RepairLayers = 2;
  int RepairPasses = 20;
  bool ComputeQuality = true;
  bool FailOnInvertedCells = false;
  bool ComputeNonOrthogonality = false;
  int NumberOfThreads = 0;
  int OneCellThickMode = DETECT;
  int RotationCenterMode = GIVEN;
  vtkMultiProcessController* Controller = nullptr;

private:
  vtkDGMFDeformFilter(const vtkDGMFDeformFilter&) = delete;
  void operator=(const vtkDGMFDeformFilter&) = delete;

  /// Steps 2-4 on the merged or given grid; `failure`, when not empty, is an error of the merge
  /// (this process then fails, and in a distributed run every process with it). A composite
  /// input's boundary patches, deformed, go to `patchesOutput`.
  int Execute(vtkUnstructuredGrid* input, vtkUnstructuredGrid* output,
    vtkUnstructuredGrid* patchesOutput, const dgmf_vtk::CompositeMesh* composite,
    const std::string& failure);

  struct Internals; ///< the caches (graph, r and f, boundary, output points) and body motions
  std::unique_ptr<Internals> Internal;
  bool LastExecutionReusedGraph = false;
  double LastGraphSeconds = 0.0;
  double LastLocationSeconds = 0.0;
  double LastDeformationSeconds = 0.0;
  double LastQualitySeconds = 0.0;
  vtkIdType LastNumberOfNodes = 0;
  vtkIdType LastNumberOfCells = 0;
};

#endif
