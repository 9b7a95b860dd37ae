/* A hunting wheelset through the C API of libwrc (wrc/wrc.h): the critical speed by simulation beside the linear one.
 *
 * The model (docs/guide/hunting.md): a wheelset of mass m and yaw inertia I, held by a lateral spring ky and a yaw
 * spring kpsi to a frame that runs at the constant speed V on straight track; its degrees of freedom are the lateral
 * displacement y and the yaw psi, its roll follows y as the rigid contact geometry gives it (roll free), each wheel
 * carries W / 2. Wheels S1002 on rails 60E1 at 1:40, gauge 1428 mm (a rolling radius difference nearly linear up to
 * +-1 mm, Hertz-like tread contact), r0 = 0.46 m. The contact forces come either from wrc's rolling contact at every
 * time step (contact=exact: one trajectory, warm-started, both wheels with their vertical force given, Kalker's exact
 * theory or FASTSIM on the elastic contact areas) or from the rigid geometry table with Kalker's linear creep law
 * (contact=table: only the geometry nonlinear; cheap, for checks).
 *
 * The linear model, written apart from the simulation and calling none of it: Wickens' 4-state wheelset (A. H.
 * Wickens, Fundamentals of Rail Vehicle Dynamics, Swets & Zeitlinger 2003; K. Knothe & S. Stichel, Rail Vehicle
 * Dynamics, Springer 2017) with Kalker's linear creep coefficients f11 = G a b C11, f22 = G a b C22, f23 = G (ab)^1.5
 * C23, f33 = G (ab)^2 C33 of the Hertz ellipse of the centred wheelset under W / 2 (wrc's rigid contact), the
 * equivalent conicity of EN 15302 (harmonic method) at the disturbance's amplitude, and the gravitational and spin
 * stiffnesses from the first harmonic of the contact angles' difference at that amplitude. Its critical speed is where
 * the largest real part of its eigenvalues crosses zero.
 *
 * The simulated critical speed: each run starts from y = y0 at rest and integrates (Heun, step dt) for T seconds; the
 * decay rate sigma is the slope of ln(amplitude) of the peaks of y (analyse()). Bisection on the sign of sigma between
 * V_lo and V_hi, the result the zero of sigma interpolated in the last bracket.
 *
 *   hunting [key=value ...]     (keys: see usage(); out=DIR writes CSV files, gnuplot scripts and PNG figures)
 *
 * Exit status: 0, or 1 on an error, or 2 when check=TOL is given and the simulated critical speed is not within TOL
 * (relative) of the linear one, or the bracket does not hold it. */
#define _POSIX_C_SOURCE 200809L /* getpid */
#include <wrc/wrc.h>

#include <complex.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

static const double kPi = 3.14159265358979323846;

/* ---------------------------------------------------------------- parameters */

typedef struct {
  double m, Iz, ky, kpsi, W;    /* kg, kg m^2, N/m, N m/rad, N (axle load) */
  double r0, gauge, E, nu, mu;  /* m, m, Pa, -, - */
  double grid;                  /* element size of the exact contact (m) */
  const char* method;           /* exact | fastsim */
  int table;                    /* 1: rigid table + Kalker's linear law; 0: wrc's rolling contact */
  double y0, dt, T;             /* disturbance (m), time step (s), length of a run (s) */
  double v_lo, v_hi;            /* bracket (m/s; 0: (1 -+ bracket) times the linear critical speed) */
  double bracket;
  int bisections;
  double creep_scale;           /* multiplies the engine's creep forces: a deliberately wrong engine, for tests */
  double check;                 /* > 0: exit 2 unless |V_sim / V_lin - 1| <= check */
  double v_cycle, T_cycle;      /* limit cycle: speed (0: 1.1 V_sim) and length (s; 0: none) */
  int bif_points, bif_small;    /* bifurcation diagram: speeds (0: none); 1: also from the small disturbance */
  double bif_from, bif_to, bif_y0, bif_T;  /* as fractions of V_sim; start amplitude (m); run length (s) */
  const char* out;              /* output folder (NULL: none) */
} Params;

static Params defaults(void) {
  Params p = {.m = 1500, .Iz = 800, .ky = 15e6, .kpsi = 1e6, .W = 150e3, .r0 = 0.46, .gauge = 1.428, .E = 210e9,
              .nu = 0.3, .mu = 0.3, .grid = 0.5e-3, .method = "exact", .table = 0, .y0 = 0.5e-3, .dt = 0.5e-3,
              .T = 1.0, .v_lo = 0, .v_hi = 0, .bracket = 0.1, .bisections = 5, .creep_scale = 1, .check = 0, .v_cycle = 0,
              .T_cycle = 0, .bif_points = 0, .bif_small = 1, .bif_from = 0.6, .bif_to = 1.2, .bif_y0 = 3e-3, .bif_T = 3,
              .out = NULL};
  return p;
}

static void usage(void) {
  fprintf(stderr,
          "usage: hunting [key=value ...]\n"
          "  m I ky kpsi W r0 gauge E nu mu   the wheelset, its suspension and the contact (SI units)\n"
          "  contact=exact|table  grid=G (m)  method=exact|fastsim\n"
          "  y0 dt T   disturbance (m), time step (s), run length (s)\n"
          "  V_lo V_hi bisections   bracket (m/s) and bisection steps\n"
          "  bracket=B   without V_lo and V_hi: (1 -+ B) times the linear critical speed (default 0.1)\n"
          "  creep_scale=S   scale the engine's creep forces (a wrong engine, for tests)\n"
          "  check=TOL   exit 2 unless the simulated critical speed is within TOL of the linear one\n"
          "  V_cycle T_cycle   the limit cycle above the critical speed (T_cycle=0: none)\n"
          "  bif_points bif_from bif_to bif_y0 bif_T   the bifurcation diagram (speeds as fractions of V_crit)\n"
          "  bif_small=0   the bifurcation diagram from the large disturbance alone\n"
          "  out=DIR   CSV files, gnuplot scripts and figures\n");
}

/* Reads one key=value; 0 on success. */
static int set_param(Params* p, const char* arg) {
  const char* eq = strchr(arg, '=');
  if (!eq) return 1;
  const size_t n = (size_t)(eq - arg);
  const char* v = eq + 1;
  struct { const char* key; double* field; } nums[] = {
      {"m", &p->m}, {"I", &p->Iz}, {"ky", &p->ky}, {"kpsi", &p->kpsi}, {"W", &p->W}, {"r0", &p->r0},
      {"gauge", &p->gauge}, {"E", &p->E}, {"nu", &p->nu}, {"mu", &p->mu}, {"grid", &p->grid}, {"y0", &p->y0},
      {"dt", &p->dt}, {"T", &p->T}, {"V_lo", &p->v_lo}, {"V_hi", &p->v_hi}, {"bracket", &p->bracket}, {"creep_scale", &p->creep_scale},
      {"check", &p->check}, {"V_cycle", &p->v_cycle}, {"T_cycle", &p->T_cycle}, {"bif_from", &p->bif_from},
      {"bif_to", &p->bif_to}, {"bif_y0", &p->bif_y0}, {"bif_T", &p->bif_T}};
  for (size_t i = 0; i < sizeof nums / sizeof nums[0]; ++i)
    if (strlen(nums[i].key) == n && strncmp(arg, nums[i].key, n) == 0) {
      char* end = NULL;
      errno = 0;
      *nums[i].field = strtod(v, &end);
      return (end == v || *end != '\0' || errno || !isfinite(*nums[i].field)) ? 2 : 0;
    }
  if (n == 10 && strncmp(arg, "bisections", n) == 0) return (p->bisections = atoi(v)) < 0 ? 2 : 0;
  if (n == 10 && strncmp(arg, "bif_points", n) == 0) return (p->bif_points = atoi(v)) < 0 ? 2 : 0;
  if (n == 9 && strncmp(arg, "bif_small", n) == 0) return (p->bif_small = atoi(v)) < 0 ? 2 : 0;
  if (n == 7 && strncmp(arg, "contact", n) == 0) {
    p->table = strcmp(v, "table") == 0;
    return (p->table || strcmp(v, "exact") == 0) ? 0 : 2;
  }
  if (n == 6 && strncmp(arg, "method", n) == 0) {
    p->method = v;
    return (strcmp(v, "exact") == 0 || strcmp(v, "fastsim") == 0) ? 0 : 2;
  }
  if (n == 3 && strncmp(arg, "out", n) == 0) return (p->out = v), 0;
  return 1;
}

/* Plausible values only: a message naming the key, 0 if all are. */
static const char* bad_param(const Params* p) {
  if (!(p->m > 0) || !(p->Iz > 0) || !(p->W > 0)) return "m, I and W must be > 0";
  if (p->ky < 0 || p->kpsi < 0) return "ky and kpsi must be >= 0";
  if (!(p->dt > 0 && p->dt <= 5e-3)) return "dt must be in (0, 5e-3] s";
  if (!(p->T >= 0.2) || p->T > 100) return "T must be in [0.2, 100] s";
  if (!(p->y0 > 0 && p->y0 < 10e-3)) return "y0 must be in (0, 10 mm)";
  if (!(p->creep_scale > 0)) return "creep_scale must be > 0";
  if (!(p->grid >= 0.05e-3 && p->grid <= 2e-3)) return "grid must be in [0.05, 2] mm";
  if (p->v_lo < 0 || p->v_hi < 0 || (p->v_hi > 0 && p->v_hi <= p->v_lo)) return "need 0 < V_lo < V_hi";
  if (!(p->bracket > 0 && p->bracket < 1)) return "bracket must be in (0, 1)";
  return NULL;
}

/* ---------------------------------------------------------------- wrc helpers */

static int failed(wrc_status s, const char* what) {
  if (s == WRC_OK) return 0;
  fprintf(stderr, "hunting: %s: %s\n", what, wrc_last_error());
  return 1;
}

/* A number of a result; NAN when the path is absent. */
static double num(const wrc_result* r, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
static double num(const wrc_result* r, const char* fmt, ...) {
  char path[160];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(path, sizeof path, fmt, ap);
  va_end(ap);
  double v = NAN;
  return wrc_result_number(r, path, &v) == WRC_OK ? v : NAN;
}

/* ---------------------------------------------------------------- the rigid geometry table */

enum { NSIDE = 2 };

/* Rows at y = y_from + i dy (uniform), roll free, Hertz's ellipse for W / 2 at every touching point. */
typedef struct {
  size_t n;
  double y_from, dy;
  double *roll, *r[NSIDE], *delta[NSIDE], *arm[NSIDE];  /* rad, m, rad (> 0 toward the track centre), m (y_c - y) */
  double *a[NSIDE], *b[NSIDE], *C11[NSIDE], *C22[NSIDE], *C23[NSIDE], *C33[NSIDE];
} Table;

static double* column(size_t n) { return calloc(n, sizeof(double)); }

static void table_free(Table* t) {
  free(t->roll);
  for (int s = 0; s < NSIDE; ++s) {
    double* cols[] = {t->r[s], t->delta[s], t->arm[s], t->a[s], t->b[s], t->C11[s], t->C22[s], t->C23[s], t->C33[s]};
    for (size_t k = 0; k < sizeof cols / sizeof cols[0]; ++k) free(cols[k]);
  }
}

/* Reads row i (1-based in the result) into index i - 1; 0 if the row has both wheels on their tread or flange. */
static int table_row(Table* t, const wrc_result* g, size_t i) {
  const char* side[NSIDE] = {"left", "right"};
  const size_t k = i - 1;
  if (num(g, "rows.%zu.converged", i) != 1) return 1;
  t->roll[k] = num(g, "rows.%zu.roll", i);
  for (int s = 0; s < NSIDE; ++s) {
    t->r[s][k] = num(g, "rows.%zu.%s.rolling_radius", i, side[s]);
    t->delta[s][k] = num(g, "rows.%zu.%s.angle", i, side[s]);
    t->arm[s][k] = num(g, "rows.%zu.%s.point.y", i, side[s]) - num(g, "rows.%zu.y", i);
    t->a[s][k] = num(g, "rows.%zu.%s.contacts.1.hertz.a", i, side[s]);
    t->b[s][k] = num(g, "rows.%zu.%s.contacts.1.hertz.b", i, side[s]);
    t->C11[s][k] = num(g, "rows.%zu.%s.contacts.1.kalker.C11", i, side[s]);
    t->C22[s][k] = num(g, "rows.%zu.%s.contacts.1.kalker.C22", i, side[s]);
    t->C23[s][k] = num(g, "rows.%zu.%s.contacts.1.kalker.C23", i, side[s]);
    t->C33[s][k] = num(g, "rows.%zu.%s.contacts.1.kalker.C33", i, side[s]);
    if (!isfinite(t->r[s][k] + t->delta[s][k] + t->a[s][k] + t->C11[s][k] + t->C33[s][k])) return 1;
  }
  return !isfinite(t->roll[k]);
}

/* The table over |y| <= y_max; 0 on success. Rows that fail (a lifted wheel, a concave pair without a Hertz
 * ellipse) end the table: it keeps the rows around y = 0 up to the first such row on either side. */
static int table_make(wrc_wheelset* ws, const Params* p, Table* t) {
  const double y_max = 10e-3, dy = 0.05e-3;
  char opts[256];
  snprintf(opts, sizeof opts, "y.from=%.17g y.to=%.17g y.step=%.17g roll=free Q=%.17g hertz_load=%.17g threads=1",
           -y_max, y_max, dy, p->W, p->W / 2);
  wrc_result* g = NULL;
  if (failed(wrc_geometry_table(ws, opts, &g), "geometry table")) return 1;
  size_t n = 0;
  wrc_result_count(g, "rows", &n);
  *t = (Table){.n = n, .y_from = -y_max, .dy = dy, .roll = column(n)};
  for (int s = 0; s < NSIDE; ++s) {
    double** cols[] = {&t->r[s], &t->delta[s], &t->arm[s], &t->a[s], &t->b[s], &t->C11[s], &t->C22[s],
                       &t->C23[s], &t->C33[s]};
    for (size_t k = 0; k < sizeof cols / sizeof cols[0]; ++k) *cols[k] = column(n);
  }
  const size_t mid = n / 2 + 1;
  size_t lo = mid, hi = mid;
  if (table_row(t, g, mid)) {
    fprintf(stderr, "hunting: the geometry table has no contact at y = 0\n");
    wrc_result_free(g);
    return 1;
  }
  while (hi < n && !table_row(t, g, hi + 1)) ++hi;
  while (lo > 1 && !table_row(t, g, lo - 1)) --lo;
  wrc_result_free(g);
  /* Keep the symmetric range both sides reach. */
  const size_t half = (hi - mid < mid - lo) ? hi - mid : mid - lo;
  const size_t first = mid - half - 1;
  t->y_from += (double)first * dy;
  t->n = 2 * half + 1;
  double** all[1 + NSIDE * 9];
  size_t c = 0;
  all[c++] = &t->roll;
  for (int s = 0; s < NSIDE; ++s) {
    all[c++] = &t->r[s], all[c++] = &t->delta[s], all[c++] = &t->arm[s], all[c++] = &t->a[s];
    all[c++] = &t->b[s], all[c++] = &t->C11[s], all[c++] = &t->C22[s], all[c++] = &t->C23[s], all[c++] = &t->C33[s];
  }
  for (size_t k = 0; k < c; ++k) memmove(*all[k], *all[k] + first, t->n * sizeof(double));
  return 0;
}

static double table_y_max(const Table* t) { return -t->y_from; }

/* Column `v` at y, linear between rows; NAN beyond the table. */
static double at(const Table* t, const double* v, double y) {
  const double u = (y - t->y_from) / t->dy;
  if (!(u >= 0 && u <= (double)(t->n - 1))) return NAN;
  size_t i = (size_t)u;
  if (i >= t->n - 1) i = t->n - 2;
  const double w = u - (double)i;
  return (1 - w) * v[i] + w * v[i + 1];
}

/* ---------------------------------------------------------------- the linear model (independent of the simulation) */

typedef struct {
  double f11, f22, f23, f33;  /* N, N, N m, N m^2 (per wheel) */
  double lambda, kg, cs;      /* conicity, gravitational stiffness (N/m), spin-creepage slope (1/m^2) */
  double b0, r0;              /* half the distance of the contact points, rolling radius (m), at y = 0 */
  double m, Iz, ky, kpsi;
} Linear;

/* The first harmonic of g(yhat sin t) over yhat: the describing function of an odd g at that amplitude. */
static double harmonic(const Table* t, double yhat, double (*g)(const Table*, double, const Params*),
                       const Params* p) {
  const int n = 256;
  double sum = 0;
  for (int k = 0; k < n; ++k) {
    const double th = 2 * kPi * (k + 0.5) / n;
    sum += g(t, yhat * sin(th), p) * sin(th);
  }
  return 2 * sum / n / yhat;
}

/* Lateral force of the normal forces toward y = 0: (W / 2)(tan dL - tan dR). */
static double gravity(const Table* t, double y, const Params* p) {
  return p->W / 2 * (tan(at(t, t->delta[0], y)) - tan(at(t, t->delta[1], y)));
}
/* The spin creepages' part that depends on y: sin dL / rL - sin dR / rR. */
static double spin(const Table* t, double y, const Params* p) {
  (void)p;
  return sin(at(t, t->delta[0], y)) / at(t, t->r[0], y) - sin(at(t, t->delta[1], y)) / at(t, t->r[1], y);
}

/* Kalker's coefficients at the centre (the rigid contact's Hertz ellipse for W / 2), EN 15302's conicity and the
 * stiffnesses at the amplitude yhat. */
static int linear_make(wrc_wheelset* ws, const Table* t, const Params* p, double yhat, Linear* L) {
  const double G = p->E / (2 * (1 + p->nu));
  const double y0 = 0, a = at(t, t->a[0], y0), b = at(t, t->b[0], y0), ab = a * b;
  *L = (Linear){.f11 = G * ab * at(t, t->C11[0], y0), .f22 = G * ab * at(t, t->C22[0], y0),
                .f23 = G * pow(ab, 1.5) * at(t, t->C23[0], y0), .f33 = G * ab * ab * at(t, t->C33[0], y0),
                .b0 = (at(t, t->arm[0], y0) - at(t, t->arm[1], y0)) / 2, .r0 = at(t, t->r[0], y0),
                .m = p->m, .Iz = p->Iz, .ky = p->ky, .kpsi = p->kpsi};
  char opts[160];
  snprintf(opts, sizeof opts, "yhat=%.17g method=harmonic roll=free", yhat);
  wrc_result* c = NULL;
  if (failed(wrc_wheelset_conicity(ws, opts, &c), "conicity")) return 1;
  size_t n = 0;
  const wrc_status s = wrc_result_numbers(c, "tan_gamma", &L->lambda, 1, &n);
  wrc_result_free(c);
  if (failed(s, "conicity's tan_gamma")) return 1;
  L->kg = harmonic(t, yhat, gravity, p);
  L->cs = harmonic(t, yhat, spin, p);
  return 0;
}

/* The state matrix at speed V (states y, psi, dy/dt, dpsi/dt), from
 *   m y''   = -(ky + kg - f23 cs) y + 2 f22 psi - 2 f22 / V y' - 2 f23 / V psi'
 *   I psi'' = -(2 f11 b0 lambda / r0 - f33 cs) y - (kpsi + 2 f23) psi + 2 f23 / V y' - 2 (f11 b0^2 + f33) / V psi'
 * (creepages xi = -+ (lambda y / r0 + b0 psi' / V), eta = y' / V - psi, phi = -+ sin(delta) / r + psi' / V). */
static void linear_matrix(const Linear* L, double V, double A[4][4]) {
  memset(A, 0, 16 * sizeof(double));
  A[0][2] = A[1][3] = 1;
  A[2][0] = -(L->ky + L->kg - L->f23 * L->cs) / L->m;
  A[2][1] = 2 * L->f22 / L->m;
  A[2][2] = -2 * L->f22 / (V * L->m);
  A[2][3] = -2 * L->f23 / (V * L->m);
  A[3][0] = -(2 * L->f11 * L->b0 * L->lambda / L->r0 - L->f33 * L->cs) / L->Iz;
  A[3][1] = -(L->kpsi + 2 * L->f23) / L->Iz;
  A[3][2] = 2 * L->f23 / (V * L->Iz);
  A[3][3] = -2 * (L->f11 * L->b0 * L->b0 + L->f33) / (V * L->Iz);
}

/* Eigenvalues of a 4 x 4 matrix: its characteristic polynomial (Faddeev-LeVerrier), the roots by Durand-Kerner. */
static void eigenvalues(double A[4][4], double complex lam[4]) {
  double M[4][4] = {{0}}, c[5] = {1, 0, 0, 0, 0}, AM[4][4];
  for (int k = 1; k <= 4; ++k) {
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) M[i][j] = (k == 1 ? 0 : M[i][j]) + (i == j ? c[k - 1] : 0);
    double tr = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        AM[i][j] = 0;
        for (int l = 0; l < 4; ++l) AM[i][j] += A[i][l] * M[l][j];
      }
    for (int i = 0; i < 4; ++i) tr += AM[i][i];
    c[k] = -tr / k;
    memcpy(M, AM, sizeof M);
  }
  /* x^4 + c1 x^3 + c2 x^2 + c3 x + c4; starts on a circle of the roots' scale. */
  const double R = 1 + fmax(fmax(fabs(c[1]), sqrt(fabs(c[2]))), fmax(cbrt(fabs(c[3])), sqrt(sqrt(fabs(c[4])))));
  for (int i = 0; i < 4; ++i) lam[i] = R * cexp(I * (0.4 + 2 * kPi * i / 4));
  for (int it = 0; it < 500; ++it) {
    double change = 0;
    for (int i = 0; i < 4; ++i) {
      const double complex z = lam[i];
      double complex pz = (((z + c[1]) * z + c[2]) * z + c[3]) * z + c[4], den = 1;
      for (int j = 0; j < 4; ++j)
        if (j != i) den *= z - lam[j];
      lam[i] = z - pz / den;
      change = fmax(change, cabs(lam[i] - z) / (1 + cabs(z)));
    }
    if (change < 1e-15) break;
  }
}

/* The eigenvalue of the largest real part at V. */
static double complex least_stable(const Linear* L, double V) {
  double A[4][4];
  double complex lam[4];
  linear_matrix(L, V, A);
  eigenvalues(A, lam);
  int k = 0;
  for (int i = 1; i < 4; ++i)
    if (creal(lam[i]) > creal(lam[k])) k = i;
  return lam[k];
}

/* The linear critical speed: the first V (scan by 1 m/s from 1 m/s, then bisection) with a root crossing into the
 * right half-plane; NAN if none below 1000 m/s. */
static double linear_critical(const Linear* L) {
  double lo = 1;
  if (creal(least_stable(L, lo)) >= 0) return NAN;
  double hi = lo;
  while (creal(least_stable(L, hi)) < 0)
    if ((hi += 1) > 1000) return NAN;
  lo = hi - 1;
  for (int i = 0; i < 60; ++i) {
    const double mid = (lo + hi) / 2;
    *(creal(least_stable(L, mid)) < 0 ? &lo : &hi) = mid;
  }
  return (lo + hi) / 2;
}

/* ---------------------------------------------------------------- the simulation */

typedef struct {
  const Params* p;
  const Table* t;
  const Linear* L;  /* only to print its decay rate beside the simulation's */
  wrc_wheelset* ws;
  wrc_trajectory* tr;
  double V, omega;  /* forward speed, axle angular velocity */
  double r_roll;    /* the radius of pure rolling: omega = V / r_roll gives the centred wheelset no traction */
  long steps;       /* time steps taken, in all runs */
  double cpu;       /* CPU seconds of all runs */
} Sim;

/* The contact forces from wrc's rolling contact: both wheels with W / 2 each (their vertical force, creep forces'
 * vertical part included) at y, psi and the roll of the rigid table. Lateral force and yaw moment on the wheelset;
 * 0 on success. */
static int forces_exact(Sim* s, const double x[4], double* Fy, double* Mz) {
  const double roll = at(s->t, s->t->roll, x[0]);
  if (!isfinite(roll)) {
    fprintf(stderr, "hunting: y = %.3f mm at V = %.2f m/s is beyond the geometry table (|y| <= %.2f mm)\n",
            x[0] * 1e3, s->V, table_y_max(s->t) * 1e3);
    return 1;
  }
  char opts[256];
  snprintf(opts, sizeof opts, "V=%.17g omega=%.17g vy=%.17g yaw_rate=%.17g mu=%.17g method=%s", s->V, s->omega, x[2],
           x[3], s->p->mu, s->p->method);
  *Fy = *Mz = 0;
  for (int side = WRC_LEFT; side <= WRC_RIGHT; ++side) {
    wrc_result* r = NULL;
    const wrc_status st = wrc_trajectory_wheel_with(s->tr, side, x[0], x[1], roll, s->p->W / 2, opts, &r);
    if (st != WRC_OK) {
      fprintf(stderr, "hunting: %s wheel at y = %.4f mm, yaw = %.4f mrad, V = %.2f m/s: %s\n",
              side ? "right" : "left", x[0] * 1e3, x[1] * 1e3, s->V, wrc_last_error());
      wrc_result_free(r);
      return 1;
    }
    const double k = s->p->creep_scale - 1;  /* the creep forces' part scaled (1: as the engine gives them) */
    *Fy += num(r, "force.y") + k * num(r, "creep_force.y");
    *Mz += num(r, "moment.z") + k * num(r, "creep_moment.z");
    wrc_result_free(r);
  }
  return 0;
}

/* Kalker's linear creep force, limited to mu N in magnitude (Coulomb's bound, without the gradual saturation of a
 * creep curve: the linear law on the nonlinear geometry). */
static double saturation(double u) { return u < 1 ? 1 : 1 / u; }

/* The contact forces from the rigid geometry table and Kalker's linear theory (contact=table). */
static int forces_table(Sim* s, const double x[4], double* Fy, double* Mz) {
  const Table* t = s->t;
  const double y = x[0], psi = x[1], V = s->V, G = s->p->E / (2 * (1 + s->p->nu));
  *Fy = *Mz = 0;
  for (int side = 0; side < NSIDE; ++side) {
    const double sg = side == 0 ? 1 : -1;  /* the left wheel's normal leans toward -y, the right's toward +y */
    const double r = at(t, t->r[side], y), d = at(t, t->delta[side], y), l = at(t, t->arm[side], y);
    const double ab = at(t, t->a[side], y) * at(t, t->b[side], y);
    if (!isfinite(r + d + l + ab)) {
      fprintf(stderr, "hunting: y = %.3f mm is beyond the geometry table (|y| <= %.2f mm)\n", y * 1e3,
              table_y_max(t) * 1e3);
      return 1;
    }
    const double xi = 1 - s->omega * r / V - x[3] * l / V, eta = x[2] / V - psi;
    const double phi = x[3] / V - sg * sin(d) * s->omega / V;
    const double f11 = G * ab * at(t, t->C11[side], y), f22 = G * ab * at(t, t->C22[side], y);
    const double f23 = G * pow(ab, 1.5) * at(t, t->C23[side], y), f33 = G * ab * ab * at(t, t->C33[side], y);
    const double N = s->p->W / 2 / cos(d);
    double fx = -f11 * xi, fy = -f22 * eta - f23 * phi;
    const double k = saturation(hypot(fx, fy) / (s->p->mu * N)) * s->p->creep_scale;
    fx *= k, fy *= k;
    const double mz = s->p->creep_scale * (f23 * eta - f33 * phi);
    *Fy += fy * cos(d) - sg * N * sin(d);
    *Mz += -l * fx + mz * cos(d);
  }
  return 0;
}

/* The centred wheelset's longitudinal creep forces at V with omega = V / r: their sum. */
static int traction(Sim* s, double r, double* Fx) {
  char opts[200];
  snprintf(opts, sizeof opts, "V=%.17g omega=%.17g mu=%.17g method=%s grids=false", s->V, s->V / r, s->p->mu,
           s->p->method);
  *Fx = 0;
  for (int side = WRC_LEFT; side <= WRC_RIGHT; ++side) {
    wrc_result* w = NULL;
    const int bad = failed(wrc_wheel(s->ws, side, 0, 0, 0, s->p->W / 2, opts, &w), "centred wheel");
    *Fx += num(w, "force.x");
    wrc_result_free(w);
    if (bad) return 1;
  }
  return 0;
}

/* The radius of pure rolling: the axle turns freely about itself, so its mean speed is the one at which the centred
 * wheelset takes no longitudinal force. The rigid rolling radius gives the elastic contact a small braking creepage
 * (its slip is taken where the wheel's material sits in the deformed contact: docs/guide/rolling.md), hence the
 * secant iteration on the radius until the two wheels' Fx sum to below 0.1 N. */
static int rolling_radius(Sim* s, double V) {
  s->V = V;
  double r0 = at(s->t, s->t->r[0], 0), r1 = r0 * (1 + 1e-4), f0, f1;
  if (traction(s, r0, &f0) || traction(s, r1, &f1)) return 1;
  for (int it = 0; it < 20 && fabs(f1) > 0.1 && f1 != f0; ++it) {
    const double r2 = r1 - f1 * (r1 - r0) / (f1 - f0);
    r0 = r1, f0 = f1, r1 = r2;
    if (traction(s, r1, &f1)) return 1;
  }
  s->r_roll = r1;
  printf("pure rolling at the radius %.6f m (rigid rolling radius %.6f m; longitudinal force %.2g N)\n", r1,
         at(s->t, s->t->r[0], 0), f1);
  return 0;
}

/* dx/dt of the state (y, psi, dy/dt, dpsi/dt). */
static int rhs(Sim* s, const double x[4], double dx[4]) {
  double Fy, Mz;
  if ((s->p->table ? forces_table : forces_exact)(s, x, &Fy, &Mz)) return 1;
  dx[0] = x[2];
  dx[1] = x[3];
  dx[2] = (Fy - s->p->ky * x[0]) / s->p->m;
  dx[3] = (Mz - s->p->kpsi * x[1]) / s->p->Iz;
  return 0;
}

/* A run: y(t) sampled at every step. */
typedef struct {
  double V;
  size_t n;
  double* y;
  double sigma, frequency;             /* of the small motion: 1/s, Hz */
  double amplitude, cycle_frequency;   /* of the run's end (its last peaks): m, Hz */
} Run;

static double process_cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* The peaks of |y| (extrema, refined by a parabola through three samples) from time `from` on; their count. */
static size_t peaks(const Run* r, double dt, double from, double* t, double* a, size_t capacity) {
  size_t n = 0;
  for (size_t k = 1; k + 1 < r->n && n < capacity; ++k) {
    const double y0 = r->y[k - 1], y1 = r->y[k], y2 = r->y[k + 1];
    if (k * dt < from || !((y1 > y0 && y1 >= y2) || (y1 < y0 && y1 <= y2))) continue;
    const double den = y0 - 2 * y1 + y2, u = den != 0 ? 0.5 * (y0 - y2) / den : 0;
    t[n] = (k + u) * dt;
    a[n++] = fabs(y1 - 0.25 * (y0 - y2) * u);
  }
  return n;
}

/* sigma: the slope of ln|peak| against time, over the peaks after the first 0.15 s (the fast modes' transient) and
 * below 4 y0 (where the motion is still the small one: a growing run is fitted until then, not along its limit
 * cycle); the frequency from the spacing of those peaks; the amplitude: the mean of the run's last four peaks. */
static void analyse(Run* r, double dt, double y0) {
  enum { CAP = 100000 };
  static double t[CAP], a[CAP];
  const size_t n = peaks(r, dt, 0.15, t, a, CAP);
  r->sigma = r->frequency = r->amplitude = r->cycle_frequency = NAN;
  if (n < 4) return;
  r->amplitude = (a[n - 1] + a[n - 2] + a[n - 3] + a[n - 4]) / 4;
  const size_t last = n < 9 ? n : 9;  /* the last four periods */
  r->cycle_frequency = (double)(last - 1) / (2 * (t[n - 1] - t[n - last]));
  size_t m = 0;
  while (m < n && a[m] < 4 * y0) ++m;
  if (m < 4) m = 4;  /* grown past 4 y0 within four peaks: their slope still tells the growth */
  double st = 0, sa = 0, stt = 0, sta = 0;
  for (size_t i = 0; i < m; ++i) {
    const double la = log(a[i]);
    st += t[i], sa += la, stt += t[i] * t[i], sta += t[i] * la;
  }
  r->sigma = (m * sta - st * sa) / (m * stt - st * st);
  r->frequency = (double)(m - 1) / (2 * (t[m - 1] - t[0]));
}

/* Runs the wheelset at V from y = y0 at rest for T seconds (Heun's method); 0 on success. */
static int simulate(Sim* s, double V, double y0, double T, Run* r) {
  s->V = V;
  s->omega = V / s->r_roll;
  if (s->tr) wrc_trajectory_reset(s->tr);
  const double dt = s->p->dt;
  const size_t n = (size_t)(T / dt + 0.5) + 1;
  *r = (Run){.V = V, .n = n, .y = malloc(n * sizeof(double))};
  double x[4] = {y0, 0, 0, 0}, k1[4], k2[4], xp[4];
  const double c0 = process_cpu();
  r->y[0] = x[0];
  for (size_t k = 1; k < n; ++k) {
    if (rhs(s, x, k1)) goto failed;
    for (int i = 0; i < 4; ++i) xp[i] = x[i] + dt * k1[i];
    if (rhs(s, xp, k2)) goto failed;
    for (int i = 0; i < 4; ++i) x[i] += 0.5 * dt * (k1[i] + k2[i]);
    r->y[k] = x[0];
  }
  s->cpu += process_cpu() - c0;
  s->steps += (long)n - 1;
  analyse(r, dt, y0);
  return 0;
failed:
  free(r->y);
  r->y = NULL;
  return 1;
}

/* ---------------------------------------------------------------- output */

/* A file written whole or not at all: opened as a temporary beside its path, renamed once complete. */
typedef struct {
  FILE* f;
  char path[4096], tmp[4200];
} Out;

static int out_open(Out* o, const char* dir, const char* name) {
  snprintf(o->path, sizeof o->path, "%s/%s", dir, name);
  snprintf(o->tmp, sizeof o->tmp, "%s.tmp%ld", o->path, (long)getpid());
  if ((o->f = fopen(o->tmp, "w"))) return 0;
  fprintf(stderr, "hunting: cannot write %s: %s\n", o->tmp, strerror(errno));
  return 1;
}

static int out_close(Out* o) {
  const int bad = ferror(o->f);
  if (fclose(o->f) != 0 || bad || rename(o->tmp, o->path) != 0) {
    fprintf(stderr, "hunting: cannot write %s\n", o->path);
    remove(o->tmp);
    return 1;
  }
  return 0;
}

/* The output folder made (with its parents) and checked writable before any run, so that a long study does not
   end in "cannot write"; 0 on success. */
static int out_ready(const char* dir) {
  char path[4096];
  if (snprintf(path, sizeof path, "%s", dir) >= (int)sizeof path) {
    fprintf(stderr, "hunting: out=%s: path too long\n", dir);
    return 1;
  }
  for (char* c = path + 1;; ++c) {
    const char end = *c;
    if (end != '/' && end != '\0') continue;
    *c = '\0';
    if (mkdir(path, 0777) != 0 && errno != EEXIST) {
      fprintf(stderr, "hunting: out=%s: cannot make %s: %s\n", dir, path, strerror(errno));
      return 1;
    }
    *c = end;
    if (end == '\0') break;
  }
  if (access(dir, W_OK) != 0) {
    fprintf(stderr, "hunting: out=%s: cannot write there: %s\n", dir, strerror(errno));
    return 1;
  }
  return 0;
}

/* y(t) of some runs, one column each: t_s, then y_mm at each run's speed. */
static int write_runs(const char* dir, const char* name, const Run* runs, int n, double dt) {
  Out o;
  if (out_open(&o, dir, name)) return 1;
  fprintf(o.f, "t_s");
  for (int j = 0; j < n; ++j) fprintf(o.f, ",y_mm at V = %.2f m/s", runs[j].V);
  fprintf(o.f, "\n");
  size_t len = 0;
  for (int j = 0; j < n; ++j) len = runs[j].n > len ? runs[j].n : len;
  for (size_t k = 0; k < len; ++k) {
    fprintf(o.f, "%.6g", k * dt);
    for (int j = 0; j < n; ++j)
      if (k < runs[j].n) fprintf(o.f, ",%.6g", runs[j].y[k] * 1e3);
      else fprintf(o.f, ",");
    fprintf(o.f, "\n");
  }
  return out_close(&o);
}

/* Writes name.gp and runs gnuplot on it in `dir` (a missing gnuplot is a note, not an error). */
static int write_file(const char* dir, const char* name, const char* text) {
  Out o;
  if (out_open(&o, dir, name)) return 1;
  fputs(text, o.f);
  return out_close(&o);
}

static int plot(const char* dir, const char* name, const char* script) {
  char gp[256], cmd[8300];
  snprintf(gp, sizeof gp, "%s.gp", name);
  if (write_file(dir, gp, script)) return 1;
  if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
    fprintf(stderr, "hunting: gnuplot not found: %s/%s not drawn\n", dir, gp);
    return 0;
  }
  snprintf(cmd, sizeof cmd, "cd '%s' && gnuplot %s", dir, gp);
  if (system(cmd) != 0) {
    fprintf(stderr, "hunting: gnuplot failed on %s/%s\n", dir, gp);
    return 1;
  }
  return 0;
}

/* ---------------------------------------------------------------- the study */

/* Bisection on the sign of the decay rate between lo and hi (runs kept: the last stable and unstable ones). Returns
 * the zero of sigma interpolated in the final bracket, NAN if the bracket does not hold one. */
static void print_run(const Sim* s, const Run* r) {
  const double complex l = least_stable(s->L, r->V);
  printf("  V = %7.3f m/s: sigma = %+8.4f 1/s, %6.3f Hz (linear model: %+8.4f 1/s, %6.3f Hz)\n", r->V, r->sigma,
         r->frequency, creal(l), fabs(cimag(l)) / (2 * kPi));
}

/* Whether a run's decay rate could be measured; if not, says why (analyse() needs four peaks after the transient). */
static int measured(const Run* r) {
  if (isfinite(r->sigma)) return 1;
  printf("  the run at %.3f m/s has fewer than four peaks of y after its first 0.15 s: no decay rate to bisect on "
         "(T too short, or a motion that does not oscillate)\n", r->V);
  return 0;
}

static double simulated_critical(Sim* s, double lo, double hi, Run* stable, Run* unstable, int* error) {
  const Params* p = s->p;
  *unstable = (Run){.V = hi, .sigma = NAN};  /* not run yet: no points */
  if ((*error = simulate(s, lo, p->y0, p->T, stable))) return NAN;
  print_run(s, stable);
  if (!measured(stable)) return NAN;
  if (!(stable->sigma < 0)) {  /* the critical speed lies below the bracket, whatever the upper speed does */
    printf("  the bracket [%.3f, %.3f] m/s does not hold the critical speed: its lower speed does not decay (the "
           "upper one is not run)\n", lo, hi);
    return NAN;
  }
  if ((*error = simulate(s, hi, p->y0, p->T, unstable))) return NAN;
  print_run(s, unstable);
  if (!measured(unstable)) return NAN;
  if (!(unstable->sigma > 0)) {
    printf("  the bracket [%.3f, %.3f] m/s does not hold the critical speed: its upper speed does not grow\n", lo, hi);
    return NAN;
  }
  for (int i = 0; i < p->bisections; ++i) {
    Run mid;
    if ((*error = simulate(s, (stable->V + unstable->V) / 2, p->y0, p->T, &mid))) return NAN;
    print_run(s, &mid);
    if (!measured(&mid)) {
      free(mid.y);
      return NAN;
    }
    Run* old = mid.sigma < 0 ? stable : unstable;
    free(old->y);
    *old = mid;
  }
  return stable->V - stable->sigma * (unstable->V - stable->V) / (unstable->sigma - stable->sigma);
}

/* One point of the bifurcation diagram: the amplitude the run ends with (0 if it decayed); NAN if it failed (the
 * message is printed; the other points go on). */
static double end_amplitude(Sim* s, double V, double y0, double T, double* frequency) {
  Run r;
  *frequency = NAN;
  if (simulate(s, V, y0, T, &r)) return NAN;
  free(r.y);
  /* A decaying run has no amplitude left: its last peaks, below a micrometre or still falling fast, count as 0. */
  if (!(r.amplitude > 1e-6 && !(r.sigma < -2))) return 0;
  *frequency = r.cycle_frequency;
  return r.amplitude;
}

/* The bifurcation diagram: at each speed the amplitude reached from a large and (bif_small) from the small
 * disturbance. */
static int bifurcation(Sim* s, double v_crit) {
  const Params* p = s->p;
  Out o;
  if (p->out && out_open(&o, p->out, "hunting_bifurcation.csv")) return 1;
  if (p->out) fprintf(o.f, "V_m_s,V_over_Vcrit,amplitude_from_large_mm,amplitude_from_small_mm,frequency_Hz\n");
  printf("bifurcation diagram (amplitude after %.1f s from y0 = %.2f mm and from %.2f mm; nan: the run failed):\n",
         p->bif_T, p->bif_y0 * 1e3, p->y0 * 1e3);
  int failures = 0;
  for (int i = 0; i < p->bif_points; ++i) {
    const double f = p->bif_points == 1 ? p->bif_from
                                         : p->bif_from + (p->bif_to - p->bif_from) * i / (p->bif_points - 1);
    double fc, fs;
    const double A1 = end_amplitude(s, f * v_crit, p->bif_y0, p->bif_T, &fc);
    const double A2 = p->bif_small ? end_amplitude(s, f * v_crit, p->y0, p->bif_T, &fs) : NAN;
    failures += isnan(A1) + (p->bif_small && isnan(A2));
    printf("  V = %7.3f m/s (%.3f V_crit): %.3f mm, %.3f mm, %.2f Hz\n", f * v_crit, f, A1 * 1e3, A2 * 1e3, fc);
    if (p->out) fprintf(o.f, "%.6g,%.6g,%.6g,%.6g,%.6g\n", f * v_crit, f, A1 * 1e3, A2 * 1e3, fc);
  }
  if (failures) printf("  %d of the runs failed (above)\n", failures);
  return p->out ? out_close(&o) : 0;
}

/* y(t): the last stable and unstable runs of the bisection above, the limit cycle (if run) below. */
static int figure_y_t(const char* dir, int n_runs) {
  char script[1500];
  snprintf(script, sizeof script,
           "set terminal pngcairo size 900,%d font 'Liberation Sans,11'\n"
           "set output 'hunting_y_t.png'\nset datafile separator ','\nset grid\n"
           "set key top right noenhanced box opaque\nset xlabel 't (s)'\nset ylabel 'y (mm)'\n"
           "set multiplot layout %d,1\n"
           "plot 'hunting_y_t.csv' using 1:2 with lines lw 1.5 title columnhead, '' using 1:3 with lines lw 1.5 "
           "title columnhead\n"
           "%s"
           "unset multiplot\n",
           n_runs > 2 ? 800 : 450, n_runs > 2 ? 2 : 1,
           n_runs > 2 ? "plot 'hunting_y_t.csv' using 1:4 with lines lw 1.5 lc 3 title columnhead\n" : "");
  return plot(dir, "hunting_y_t", script);
}

/* The bifurcation diagram, with the linear and the simulated critical speeds marked. */
static int figure_bifurcation(const char* dir, double v_lin, double v_sim) {
  char script[1500];
  snprintf(script, sizeof script,
           "set terminal pngcairo size 900,500 font 'Liberation Sans,11'\n"
           "set output 'hunting_bifurcation.png'\nset datafile separator ','\nset grid\n"
           "set xlabel 'V (m/s)'\nset ylabel 'amplitude of y (mm)'\nset key top left box opaque\n"
           "set arrow from %.6g, graph 0 to %.6g, graph 1 nohead dt 2 lc rgb 'black'\n"
           "set arrow from %.6g, graph 0 to %.6g, graph 1 nohead dt 3 lc rgb 'red'\n"
           "set label 'linear' at %.6g, graph 0.95 right offset -0.5,0\n"
           "set label 'simulated' at %.6g, graph 0.88 right offset -0.5,0 tc rgb 'red'\n"
           "plot 'hunting_bifurcation.csv' using 1:3 with points pt 7 ps 1.3 title 'from the large disturbance', \\\n"
           "     '' using 1:4 with points pt 6 ps 1.8 title 'from the small disturbance'\n",
           v_lin, v_lin, v_sim, v_sim, v_lin, v_sim);
  return plot(dir, "hunting_bifurcation", script);
}

static int study(Sim* s, const Linear* L, double v_lin) {
  const Params* p = s->p;
  const double lo = p->v_lo > 0 ? p->v_lo : (1 - p->bracket) * v_lin;
  const double hi = p->v_hi > 0 ? p->v_hi : (1 + p->bracket) * v_lin;
  printf("simulation: %s, y0 = %.3f mm, dt = %.3g ms, %.2f s per run, bisection in [%.3f, %.3f] m/s%s\n",
         p->table ? "rigid geometry table + Kalker's linear law" : "wrc's rolling contact", p->y0 * 1e3, p->dt * 1e3,
         p->T, lo, hi, p->creep_scale != 1 ? " (creep forces scaled)" : "");
  Run runs[3];
  int error = 0;
  const double v_sim = simulated_critical(s, lo, hi, &runs[0], &runs[1], &error);
  if (error) return 1;
  const double ratio = v_sim / v_lin;
  printf("critical speed: linear %.3f m/s (%.1f km/h), simulated %.3f m/s (%.1f km/h), ratio %.4f\n", v_lin,
         v_lin * 3.6, v_sim, v_sim * 3.6, ratio);
  printf("runtime: %.3f s CPU per simulated second (%ld steps of %.3g ms, 2 contact evaluations per step)\n",
         s->cpu / (s->steps * p->dt), s->steps, p->dt * 1e3);
  int n_runs = 2, rc = 0;
  if (p->T_cycle > 0 && isfinite(v_sim)) {
    const double v = p->v_cycle > 0 ? p->v_cycle : 1.1 * v_sim;
    if (simulate(s, v, p->y0, p->T_cycle, &runs[2])) return 1;
    ++n_runs;
    printf("limit cycle at V = %.3f m/s: amplitude %.3f mm, frequency %.3f Hz (linear model's at V_crit: %.3f Hz)\n",
           v, runs[2].amplitude * 1e3, runs[2].cycle_frequency, fabs(cimag(least_stable(L, v_lin))) / (2 * kPi));
  }
  if (p->out && (write_runs(p->out, "hunting_y_t.csv", runs, n_runs, p->dt) || figure_y_t(p->out, n_runs)))
    rc = 1;
  for (int j = 0; j < n_runs; ++j) free(runs[j].y);
  if (!rc && p->bif_points > 0 && isfinite(v_sim))
    rc = bifurcation(s, v_sim) || (p->out && figure_bifurcation(p->out, v_lin, v_sim));
  if (rc) return 1;
  if (p->check > 0 && !(fabs(ratio - 1) <= p->check)) {
    printf("CHECK FAILED: the simulated critical speed is not within %.1f %% of the linear one\n", 100 * p->check);
    return 2;
  }
  if (p->check > 0) printf("check passed: within %.1f %%\n", 100 * p->check);
  return 0;
}

static void print_linear(const Linear* L, double v_lin, double yhat) {
  printf("linear model at the amplitude %.3f mm: lambda = %.4f (EN 15302, harmonic), kg = %.4g N/m, spin slope "
         "%.4g 1/m^2 (f23 cs = %.4g N/m),\n  f11 = %.4g N, f22 = %.4g N, f23 = %.4g N m, f33 = %.4g N m^2, b0 = %.4f m, "
         "r0 = %.5f m\n", yhat * 1e3, L->lambda, L->kg, L->cs, L->f23 * L->cs, L->f11, L->f22, L->f23, L->f33, L->b0,
         L->r0);
  if (isfinite(v_lin))
    printf("linear critical speed %.3f m/s (%.1f km/h), hunting frequency there %.3f Hz\n", v_lin, v_lin * 3.6,
           fabs(cimag(least_stable(L, v_lin))) / (2 * kPi));
  else
    printf("linear model: no critical speed below 1000 m/s\n");
}

int main(int argc, char** argv) {
  setvbuf(stdout, NULL, _IOLBF, 0);  /* progress, line by line, also into a file */
  Params p = defaults();
  for (int i = 1; i < argc; ++i) {
    if (strcmp(argv[i], "help") == 0) return usage(), 0;
    const int bad = set_param(&p, argv[i]);
    if (bad) {
      fprintf(stderr, "hunting: %s '%s'\n", bad == 1 ? "unknown argument" : "bad value in", argv[i]);
      usage();
      return 1;
    }
  }
  const char* why = bad_param(&p);
  if (!why && p.out && strchr(p.out, '\'')) why = "out must not contain a quote";
  if (why) {
    fprintf(stderr, "hunting: %s\n", why);
    return 1;
  }
  if (p.out && out_ready(p.out)) return 1;
  if (wrc_abi_version() != WRC_ABI_VERSION) {
    fprintf(stderr, "hunting: libwrc ABI %d, this program was built for %d\n", wrc_abi_version(), WRC_ABI_VERSION);
    return 1;
  }
  wrc_profile *wheel = NULL, *rail = NULL;
  wrc_wheelset* ws = NULL;
  char opts[256];
  snprintf(opts, sizeof opts, "radius=%.17g gauge=%.17g cant=0.025 E=%.17g nu=%.17g grid=%.17g", p.r0, p.gauge, p.E,
           p.nu, p.grid);
  if (failed(wrc_profile_load("profiles/s1002.lua", NULL, &wheel), "wheel profile") ||
      failed(wrc_profile_load("profiles/60e1.lua", NULL, &rail), "rail profile") ||
      failed(wrc_wheelset_new(wheel, rail, opts, &ws), "wheelset"))
    return 1;
  printf("wrc %s: S1002 on 60E1, 1:40, gauge %.1f mm, r0 %.0f mm; m = %.0f kg, I = %.0f kg m^2, ky = %.3g N/m, "
         "kpsi = %.3g N m/rad, W = %.0f kN, mu = %.2f\n", wrc_version(), p.gauge * 1e3, p.r0 * 1e3, p.m, p.Iz, p.ky,
         p.kpsi, p.W / 1e3, p.mu);
  Table t;
  Linear L;
  int rc = 1;
  if (!table_make(ws, &p, &t)) {
    if (!linear_make(ws, &t, &p, p.y0, &L)) {
      const double v_lin = linear_critical(&L);
      print_linear(&L, v_lin, p.y0);
      Sim s = {.p = &p, .t = &t, .L = &L, .ws = ws};
      if (isfinite(v_lin) && (p.table || !failed(wrc_trajectory_new(ws, "extrapolate=false", &s.tr), "trajectory"))) {
        s.r_roll = at(&t, t.r[0], 0);
        if (!p.table) printf("exact contact: grid %.2f mm, method %s\n", p.grid * 1e3, p.method);
        rc = (p.table || !rolling_radius(&s, v_lin)) ? study(&s, &L, v_lin) : 1;
      }
      wrc_trajectory_free(s.tr);
    }
    table_free(&t);
  }
  wrc_wheelset_free(ws);
  wrc_profile_free(rail);
  wrc_profile_free(wheel);
  return rc;
}
