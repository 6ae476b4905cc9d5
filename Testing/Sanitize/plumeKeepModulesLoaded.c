/*
 * LD_PRELOAD shim for the sanitizer run: dlclose() does nothing, so every
 * dlopen()ed module stays mapped until the process ends.
 *
 * Why: LeakSanitizer checks for leaks at exit, after Mesa's GLX driver
 * (libGLX_mesa, libgallium, libLLVM) and Open MPI's plugins (mca_*.so, loaded
 * by hypre's MPI) were unloaded by dlclose(). What they still held is then
 * reported with frames in "<unknown module>", which no suppression can name,
 * so leaks could not be checked at all. With the modules kept mapped the
 * frames carry the module's name and Testing/Sanitize/lsan.supp suppresses
 * exactly those libraries, never Plume's code.
 *
 * Built without sanitizer flags (an uninstrumented library can be preloaded
 * into every process of a test: bash, cmake, Xvfb, plume), only in a
 * PLUME_SANITIZE build; scripts/test-sanitize.sh sets LD_PRELOAD to it.
 */
int dlclose(void* handle)
{
  (void)handle;
  return 0;
}
