/* The paper's wheelset from C: S1002 wheels on 60E1 rails (1:40, gauge 1435 mm, r0 = 450 mm), the static
 * equilibrium at y = 3 mm under Q = 200 kN, through the C API of libwrc (wrc/wrc.h).
 *
 *   cc paper_equilibrium.c $(pkg-config --cflags --libs wrc) -o paper_equilibrium && ./paper_equilibrium
 *   (or CMake: find_package(wrc) and link wrc::wrc; see CMakeLists.txt beside this file)
 *
 * Prints Y/Q, z, roll and each contact patch: normal force, contact angle, area, peak pressure. */
#include <wrc/wrc.h>

#include <math.h>
#include <stdio.h>

/* Prints the failed call's message and leaves. */
static int check(wrc_status s, const char* what) {
  if (s == WRC_OK) return 0;
  fprintf(stderr, "%s: %s\n", what, wrc_last_error());
  return 1;
}

static double number(const wrc_result* r, const char* path) {
  double v = NAN;
  wrc_result_number(r, path, &v);
  return v;
}

int main(void) {
  if (wrc_abi_version() != WRC_ABI_VERSION) {
    fprintf(stderr, "libwrc ABI %d, this program was built for %d\n", wrc_abi_version(), WRC_ABI_VERSION);
    return 1;
  }
  wrc_profile *wheel = NULL, *rail = NULL;
  wrc_wheelset* ws = NULL;
  wrc_result* e = NULL;
  if (check(wrc_profile_load("profiles/s1002.lua", NULL, &wheel), "wheel") ||
      check(wrc_profile_load("profiles/60e1.lua", NULL, &rail), "rail") ||
      check(wrc_wheelset_new(wheel, rail, "gauge=1.435 cant=0.025 radius=0.45", &ws), "wheelset") ||
      check(wrc_equilibrium(ws, 3e-3, 0.0, 200e3, "grids=false", &e), "equilibrium"))
    return 1;
  printf("wrc %s, equilibrium at y = 3 mm, Q = 200 kN\n", wrc_version());
  printf("Y/Q = %.6f\nz = %.6f mm\nroll = %.6f mrad\n", number(e, "Y_Q"), number(e, "z") * 1e3,
         number(e, "roll") * 1e3);
  const char* sides[2] = {"left", "right"};
  for (int s = 0; s < 2; ++s) {
    char path[128];
    size_t n = 0;
    snprintf(path, sizeof path, "%s.patches", sides[s]);
    wrc_result_count(e, path, &n);
    for (size_t i = 1; i <= n; ++i) {
      double v[4];
      const char* field[4] = {"normal_force", "angle", "area", "pmax"};
      for (int k = 0; k < 4; ++k) {
        snprintf(path, sizeof path, "%s.patches.%zu.%s", sides[s], i, field[k]);
        v[k] = number(e, path);
      }
      printf("%s patch %zu: N = %.3f kN, contact angle %.3f deg, area %.2f mm2, pmax %.1f MPa\n", sides[s], i,
             v[0] / 1e3, v[1] * 180.0 / M_PI, v[2] * 1e6, v[3] / 1e6);
    }
  }
  wrc_result_free(e);
  wrc_wheelset_free(ws);
  wrc_profile_free(rail);
  wrc_profile_free(wheel);
  return 0;
}
