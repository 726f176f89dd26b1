/**
 * @class   vtkAnalyticMeshSource
 * @brief   Generated hexahedral or tetrahedral meshes of [-1,1]^3 carrying analytic point fields.
 *
 * A grid of Resolution[0] x Resolution[1] x Resolution[2] hexahedra over [-1,1]^3, optionally
 * distorted (a smooth twist about z, a random jitter of interior points that keeps cells valid, or a
 * 45 degree rotation about z), optionally split into tetrahedra by vtkHexahedraToTetrahedra.
 * Every point carries the three fields `Linear`, `MarschnerLobb` and `Steiner` (see uvAnalyticMesh.h),
 * evaluated at the final, distorted position; the one chosen by Field is the active scalars.
 * The meshes feed the project's tests, its benchmark and the bundled files in Data/.
 */
#ifndef vtkAnalyticMeshSource_h
#define vtkAnalyticMeshSource_h

#include "vtkUnstructuredVolumeModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

class VTKUNSTRUCTUREDVOLUME_EXPORT vtkAnalyticMeshSource : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkAnalyticMeshSource* New();
  vtkTypeMacro(vtkAnalyticMeshSource, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Fields
  {
    LINEAR = 0,
    MARSCHNER_LOBB = 1,
    STEINER = 2
  };
  enum Distortions
  {
    NO_DISTORTION = 0,
    TWIST = 1,
    JITTER = 2,
    ROTATE_45 = 3
  };
  enum CellKinds
  {
    HEXAHEDRA = 0,
    SIX_TETRAHEDRA = 1,
    FIVE_TETRAHEDRA = 2
  };

  /// Cells per axis, at least 1 each. Default 16 x 16 x 16.
  vtkSetVector3Macro(Resolution, int);
  vtkGetVector3Macro(Resolution, int);

  /// The active scalar field. Default MARSCHNER_LOBB.
  vtkSetClampMacro(Field, int, LINEAR, STEINER);
  vtkGetMacro(Field, int);

  vtkSetClampMacro(Distortion, int, NO_DISTORTION, ROTATE_45);
  vtkGetMacro(Distortion, int);

  /// Twist angle in radians from z = -1 to z = 1. Default 1.
  vtkSetMacro(TwistAngle, double);
  vtkGetMacro(TwistAngle, double);

  /// Jitter of interior points, as a fraction of the spacing, clamped to [0, 0.15]. Default 0.1.
  vtkSetClampMacro(JitterFraction, double, 0.0, 0.15);
  vtkGetMacro(JitterFraction, double);

  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);

  vtkSetClampMacro(CellKind, int, HEXAHEDRA, FIVE_TETRAHEDRA);
  vtkGetMacro(CellKind, int);

protected:
  vtkAnalyticMeshSource();
  ~vtkAnalyticMeshSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Resolution[3] = { 16, 16, 16 };
  int Field = MARSCHNER_LOBB;
  int Distortion = NO_DISTORTION;
  double TwistAngle = 1.0;
  double JitterFraction = 0.1;
  int Seed = 1;
  int CellKind = HEXAHEDRA;

private:
  vtkAnalyticMeshSource(const vtkAnalyticMeshSource&) = delete;
  void operator=(const vtkAnalyticMeshSource&) = delete;
};

#endif
