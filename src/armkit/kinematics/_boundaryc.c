/* armkit.kinematics._boundaryc: the position-only closed form's boundary search for one
 * base branch, compiled (issue 29 item 3: boundary targets at most 2x the normal path).
 *
 * The same search as kinematics/_pitch_range.py's boundary_pitch (lanes, numpy), which
 * is its reference (tests/kinematics/test_pitch_range.py pins them together): every
 * boundary point is where the wrist circle about the target T (radius L3) meets another
 * circle - the elbow at a limit, straight or folded (about the shoulder), the shoulder at
 * a limit (about a fixed elbow point E), the wrist at a limit (links 2 and 3 one rigid
 * link U) - and the nearest to the wanted pitch at which every planar joint is inside its
 * range (dot products of the links) is taken; ties go to the first in that order.
 *
 * The circles come packed as 48 float64 by kinematics/_boundary_fast.py (``pack``):
 *   c1x c1z v2x v2z cK sK ck sk l1^2 l2^2 l3^2 lateral,
 *   n_elbows, 4 x (d^2, ax, ay), 2 x shoulder (ex, ez), 2 x wrist (ux, uz, u^2),
 *   n_ranges, 3 x range (k, cos, sin, least).
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>

#define PACKED 48
#define TWO_PI (2.0 * M_PI)

typedef struct { /* one boundary point: link 3 (T - W), the elbow E, the wrist W */
    double lx, lz, ex, ez, wx, wz;
} Point;

static double pitch_of_phi(double c, double s, double r, double rho) {
    /* kinematics/_pose.py pitch_of_phi in floats */
    int axis = fabs(r) < 1e-12 || rho < 1e-12;
    return atan2(s, axis ? fabs(c) : c * r / rho);
}

static int meet(double tx, double tz, double ax, double az, double ra2, double rb2,
                double *out) {
    /* the points where the circle about (ax, az) of squared radius ra2 meets the circle
     * about (tx, tz) of squared radius rb2 [m]: 2 (x, z) pairs in out, or none (0) */
    double dx = tx - ax, dz = tz - az;
    double d2 = dx * dx + dz * dz + 1e-300;
    double along = (d2 + ra2 - rb2) / (2.0 * d2);
    double h2 = ra2 / d2 - along * along;
    if (!(h2 >= -1e-12)) return 0;
    double h = sqrt(fabs(h2));
    double mx = ax + along * dx, mz = az + along * dz;
    out[0] = mx - h * dz; out[1] = mz + h * dx;
    out[2] = mx + h * dz; out[3] = mz - h * dx;
    return 2;
}

static int fits(const double *ranges, int n, const Point *pt) {
    /* every planar joint inside its range: each link's dot product with its range's middle */
    double links[3][2] = {{pt->ex, pt->ez}, {pt->wx - pt->ex, pt->wz - pt->ez}, {pt->lx, pt->lz}};
    for (int i = 0; i < n; i++) {
        const double *g = ranges + 4 * i;
        int k = (int)g[0];
        double cm = g[1], sm = g[2], least = g[3];
        double ax = links[k][0], az = links[k][1];
        double px = k ? links[k - 1][0] : 1.0, pz = k ? links[k - 1][1] : 0.0;
        if (!((px * cm - pz * sm) * ax + (px * sm + pz * cm) * az >= least)) return 0;
    }
    return 1;
}

typedef struct {
    const double *c; /* the packed circles */
    double r, rho, want, tx, tz, wx3, wz3;
    int by_pitch;
    double gap;
    Point best;
    int found;
} Search;

static void consider(Search *s, double wx, double wz, double ex, double ez) {
    const double *c = s->c;
    Point pt = {s->tx - wx, s->tz - wz, ex, ez, wx, wz};
    double d;
    if (s->by_pitch) {
        double ck = c[6], sk = c[7];
        d = fabs(pitch_of_phi(pt.lx * ck - pt.lz * sk, pt.lx * sk + pt.lz * ck, s->r, s->rho) -
                 s->want);
        if (d > M_PI) d = TWO_PI - d;
    } else {
        d = -(pt.lx * s->wx3 + pt.lz * s->wz3);
    }
    if (!(d < s->gap) || !fits(c + 36, (int)c[35], &pt)) return;
    s->gap = d;
    s->best = pt;
    s->found = 1;
}

static void search(const double *c, double r, double z, double rho, double want, double *gap,
                   double *pitch) {
    double c1x = c[0], c1z = c[1], v2x = c[2], v2z = c[3], cK = c[4], sK = c[5];
    double l1sq = c[8], l2sq = c[9], l3sq = c[10], lateral = c[11];
    Search s = {.c = c, .r = r, .rho = rho, .want = want, .tx = r - c1x, .tz = z - c1z};
    s.by_pitch = lateral != 0.0 || rho < 1e-12 || (-1e-12 < r && r < 1e-12);
    double co = r > 0 ? cos(want) : -cos(want), si = sin(want);
    s.wx3 = co * cK + si * sK; /* link 3's direction at want */
    s.wz3 = si * cK - co * sK;
    s.gap = INFINITY;
    double w[4];
    const double *el = c + 13;
    for (int i = 0; i < (int)c[12]; i++, el += 3) /* elbow at a limit, straight, folded */
        if (meet(s.tx, s.tz, 0.0, 0.0, el[0], l3sq, w))
            for (int k = 0; k < 4; k += 2)
                consider(&s, w[k], w[k + 1], el[1] * w[k] + el[2] * w[k + 1],
                         el[1] * w[k + 1] - el[2] * w[k]);
    for (int i = 0; i < 2; i++) { /* shoulder at a limit: E fixed */
        double ex = c[25 + 2 * i], ez = c[26 + 2 * i];
        if (meet(s.tx, s.tz, ex, ez, l2sq, l3sq, w))
            for (int k = 0; k < 4; k += 2) consider(&s, w[k], w[k + 1], ex, ez);
    }
    for (int i = 0; i < 2; i++) { /* wrist at a limit: links 2 and 3 one rigid link U */
        double ux = c[29 + 3 * i], uz = c[30 + 3 * i], u2 = c[31 + 3 * i];
        if (!meet(s.tx, s.tz, 0.0, 0.0, l1sq, u2, w)) continue;
        for (int k = 0; k < 4; k += 2) {
            double ex = w[k], ez = w[k + 1];
            double rc = (ux * (s.tx - ex) + uz * (s.tz - ez)) / u2;
            double rs = (ux * (s.tz - ez) - uz * (s.tx - ex)) / u2;
            consider(&s, ex + rc * v2x - rs * v2z, ez + rs * v2x + rc * v2z, ex, ez);
        }
    }
    double lx = s.found ? s.best.lx : 0.0, lz = s.found ? s.best.lz : 0.0;
    double ck = s.found ? c[6] : 0.0, sk = s.found ? c[7] : 0.0;
    *gap = s.gap;
    *pitch = pitch_of_phi(lx * ck - lz * sk, lx * sk + lz * ck, r, rho);
}

/* ---------------------------------------------------------------- the Python interface */

static PyObject *boundary(PyObject *self, PyObject *const *args, Py_ssize_t nargs) {
    if (nargs != 5 || !PyBytes_Check(args[0]) ||
        PyBytes_GET_SIZE(args[0]) != PACKED * (Py_ssize_t)sizeof(double)) {
        PyErr_SetString(PyExc_TypeError,
                        "boundary(packed: 48 float64 as bytes, r, z, rho, want: float)");
        return NULL;
    }
    double v[4];
    for (int i = 0; i < 4; i++) {
        v[i] = PyFloat_AsDouble(args[i + 1]);
        if (v[i] == -1.0 && PyErr_Occurred()) return NULL;
    }
    const double *c = (const double *)PyBytes_AS_STRING(args[0]);
    if (c[12] < 0 || c[12] > 4 || c[35] < 0 || c[35] > 3) {
        PyErr_SetString(PyExc_ValueError, "packed circles: up to 4 elbows and 3 ranges");
        return NULL;
    }
    double gap, pitch;
    search(c, v[0], v[1], v[2], v[3], &gap, &pitch);
    return Py_BuildValue("(dd)", gap, pitch);
}

static PyMethodDef methods[] = {
    {"boundary", (PyCFunction)(void (*)(void))boundary, METH_FASTCALL,
     "boundary(packed, r, z, rho, want) -> (gap, pitch [rad]): the boundary point nearest "
     "the wanted pitch at which the arm fits, on one base branch (see _boundaryc.c)"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_boundaryc",
    "armkit's position-only boundary search, compiled (see _boundaryc.c).", -1, methods,
};

PyMODINIT_FUNC PyInit__boundaryc(void) { return PyModule_Create(&module); }
