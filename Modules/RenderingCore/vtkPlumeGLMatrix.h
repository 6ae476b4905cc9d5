// Row-major double matrices as GL uniforms. Plume's mappers compose their
// matrices in double precision, row-major like vtkMatrix4x4; GL wants
// column-major floats. (vtkShaderProgram::SetUniformMatrix(vtkMatrix4x4*)
// does not transpose: it serves VTK's own pre-transposed key matrices.)
#ifndef vtkPlumeGLMatrix_h
#define vtkPlumeGLMatrix_h

#include "vtkShaderProgram.h" // For SetUniformMatrix4x4/3x3

namespace plume
{
/** Sets the mat4 uniform `name` of `program` to the row-major `m`. */
inline bool SetUniformMatrix4x4(vtkShaderProgram* program, const char* name, const double m[16])
{
  float gl[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      gl[4 * c + r] = static_cast<float>(m[4 * r + c]);
    }
  }
  return program->SetUniformMatrix4x4(name, gl);
}

/** Sets the mat3 uniform `name` of `program` to the row-major `m`. */
inline bool SetUniformMatrix3x3(vtkShaderProgram* program, const char* name, const double m[9])
{
  float gl[9];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      gl[3 * c + r] = static_cast<float>(m[3 * r + c]);
    }
  }
  return program->SetUniformMatrix3x3(name, gl);
}
}

#endif
