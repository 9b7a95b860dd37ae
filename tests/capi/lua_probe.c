/* A C program that loads a Simpack rail (.prr) and a text profile through libwrc, run with lua_probe_shim preloaded
 * (LD_PRELOAD): no Lua state may be made meanwhile. Then it loads the shipped Lua definition of the 60E1 rail, which
 * must make one (the sandbox's): that shows the probe sees libwrc's Lua at all.
 *   lua_probe SAMPLES_DIR TMP_DIR */
#include "wrc/wrc.h"

#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

static int (*lua_states)(void);

static int fail(const char* what) {
  fprintf(stderr, "lua_probe: %s\n", what);
  return 1;
}

/* Loads `path` with `options`; returns its number of points (0 on failure, with the message printed). */
static size_t load(const char* path, const char* options, wrc_profile** p) {
  size_t n = 0;
  if (wrc_profile_load(path, options, p) != WRC_OK) {
    fprintf(stderr, "lua_probe: %s\n", wrc_last_error());
    return 0;
  }
  wrc_profile_points(*p, NULL, NULL, 0, &n); /* WRC_TOO_SMALL with the count */
  return n;
}

/* A rail head every millimetre, y = -20 .. 20 mm, z = -y^2/600 mm, as a text file. */
static int write_text_profile(const char* path) {
  FILE* f = fopen(path, "w");
  if (!f) return 0;
  for (int i = -20; i <= 20; ++i) fprintf(f, "%d %.17g\n", i, -(double)(i * i) / 600.0);
  return fclose(f) == 0;
}

static int check_text_points(wrc_profile* p) {
  double y[41], z[41];
  size_t n = 0;
  if (wrc_profile_points(p, y, z, 41, &n) != WRC_OK || n != 41) return 0;
  for (int i = 0; i < 41; ++i) {
    const double ym = (i - 20) * 1e-3, zm = -(double)((i - 20) * (i - 20)) / 600.0 * 1e-3;
    if (fabs(y[i] - ym) > 1e-15 || fabs(z[i] - zm) > 1e-15) return 0;
  }
  return 1;
}

int main(int argc, char** argv) {
  if (argc != 3) return fail("usage: lua_probe SAMPLES_DIR TMP_DIR");
  *(void**)(&lua_states) = dlsym(RTLD_DEFAULT, "wrc_probe_lua_states");
  if (!lua_states) return fail("the probe is not loaded: run with LD_PRELOAD=<build>/tests/capi/liblua_probe_shim.so");

  char prr[4096], txt[4096];
  snprintf(prr, sizeof prr, "%s/60e1_canted.prr", argv[1]);
  snprintf(txt, sizeof txt, "%s/lua_probe_%ld.txt", argv[2], (long)getpid());
  if (!write_text_profile(txt)) return fail("cannot write the text profile");
  wrc_profile *simpack = NULL, *text = NULL, *definition = NULL;
  const size_t n_prr = load(prr, NULL, &simpack);
  const size_t n_txt = load(txt, "kind=rail", &text);
  remove(txt);
  if (n_prr < 3 || n_txt == 0) return fail("a file did not load");
  if (!check_text_points(text)) return fail("the text profile's points are not the file's (mm -> m)");
  const int after_files = lua_states();
  printf("Simpack rail (%zu points) and text profile (%zu points) loaded: %d calls making a Lua state\n", n_prr,
         n_txt, after_files);

  const size_t n_lua = load("profiles/60e1.lua", NULL, &definition);
  const int after_definition = lua_states();
  printf("Lua definition profiles/60e1.lua (%zu points) loaded: %d calls making a Lua state in all\n", n_lua,
         after_definition);
  wrc_profile_free(simpack);
  wrc_profile_free(text);
  wrc_profile_free(definition);
  if (after_files != 0) return fail("loading a Simpack and a text file made a Lua state");
  if (n_lua < 3 || after_definition < 1)
    return fail("the probe saw no Lua state made for a Lua definition: it does not see the Lua that libwrc uses");
  return 0;
}
