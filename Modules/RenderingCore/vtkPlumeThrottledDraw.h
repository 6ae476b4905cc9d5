// Draw calls split into chunks, with at most a few chunks queued in the
// driver. llvmpipe bins a whole draw before its threads rasterize it, and
// queues binned scenes while the rasterizer is behind, so one draw of
// millions of lines or screen boxes holds hundreds of MB to GB of binned data;
// a fence after each chunk and a wait for the chunk `inFlight` draws back
// bound that memory whatever the primitive count (shared by the glyph and
// sheet mappers; measured figures in their class documentation).
#ifndef vtkPlumeThrottledDraw_h
#define vtkPlumeThrottledDraw_h

#include "PlumeRenderingCoreModule.h" // For export macro
#include "vtkType.h"              // For vtkIdType

namespace plume
{
/**
 * glDrawArrays(`mode`, ...) of `count` primitives of `perPrimitive` vertices
 * each, starting at vertex 0, in draws of at most `chunk` primitives (0: one
 * draw). gl_VertexID keeps counting across the draws (it includes their
 * first vertex), so shaders see the same vertex ids as in one draw. With
 * `inFlight` > 0, at most that many earlier chunks are unfinished when the
 * next one is submitted. The image is the same as one draw's. Vertex
 * indices are GLint: count x perPrimitive must stay below 2^31 (a GL limit
 * of glDrawArrays itself). Returns the number of draw calls made.
 */
PLUMERENDERINGCORE_EXPORT int DrawArraysThrottled(
  unsigned int mode, int perPrimitive, vtkIdType count, vtkIdType chunk, int inFlight);
}

#endif
