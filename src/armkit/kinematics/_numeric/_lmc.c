/* armkit.kinematics._numeric._lmc: the LM (damped least squares) IK solver, compiled.
 *
 * The whole solve runs here, with no Python in the loop: forward kinematics of the
 * chain (per joint a fixed transform F, then a turn about its z axis, as
 * kinematics/_steps.py describes it), the task residual and its weighted Jacobian
 * (kinematics/_residual.py), the damped least-squares step by Cholesky on the
 * smaller of J J^T + lam I and J^T J + lam I, joints at a limit pushing outwards
 * frozen, the first joint's exact turn, convergence and stall tests, and restarts
 * from seeded random joint vectors (splitmix64). One target or N targets (the GIL
 * released). tests/numeric/lm_reference.py is the same method in Python; the tests
 * pin this kernel to it.
 *
 * The chain comes packed as float64 (see kinematics/_numeric/_lm.py, ``pack``):
 *   dof, then per joint R (9, row-major) t (3) sign offset, then the tool's R (9) t (3),
 *   lower (dof), upper (dof), reach [m], weight [m/rad].
 * A target is 13 float64: p (3) [m], pitch [rad], R (9, row-major); mode 0 = position,
 * 1 = position + pitch, 2 = pose.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define MAXDOF 64
#define RUN_ITERATIONS 20
#define STALL_ITERATIONS 4
#define MAX_RESTARTS 150
#define MAX_STEP 1.0
#define MU0 0.1
#define MU_DOWN 0.1
#define MU_UP 8.0
#define CANDIDATES 8
#define HEAD 14 /* doubles per joint in the packed chain */

typedef struct {
    int dof;
    const double *joints; /* dof * HEAD */
    const double *tool;   /* 12 */
    const double *lower, *upper;
    double reach, weight;
} Chain;

typedef struct {
    int mode;
    double p[3], pitch, R[9];
    double tol_pos, tol_ang;
} Task;

typedef struct { /* a chain state: tool point, rotation columns, joint axes and origins */
    double p[3], a[3], b[3], c[3];
    double jw[MAXDOF][3], o[MAXDOF][3];
} State;

typedef struct {
    double e[6];
    int m;
    double pos, ang, cost;
} Residual;

/* ---------------------------------------------------------------- forward kinematics */

static void fixed_apply(const double *F, double *p, double *a, double *b, double *c) {
    /* columns new_j = sum_k F[k][j] col_k; p += sum_k F[k][3] col_k; F as R (9) t (3) */
    double na[3], nb[3], nc[3];
    for (int x = 0; x < 3; x++) {
        p[x] += F[9] * a[x] + F[10] * b[x] + F[11] * c[x];
        na[x] = F[0] * a[x] + F[3] * b[x] + F[6] * c[x];
        nb[x] = F[1] * a[x] + F[4] * b[x] + F[7] * c[x];
        nc[x] = F[2] * a[x] + F[5] * b[x] + F[8] * c[x];
    }
    memcpy(a, na, sizeof na);
    memcpy(b, nb, sizeof nb);
    memcpy(c, nc, sizeof nc);
}

static void forward(const Chain *ch, const double *q, State *st) {
    double *p = st->p, *a = st->a, *b = st->b, *c = st->c;
    p[0] = p[1] = p[2] = 0.0;
    a[0] = 1.0; a[1] = 0.0; a[2] = 0.0;
    b[0] = 0.0; b[1] = 1.0; b[2] = 0.0;
    c[0] = 0.0; c[1] = 0.0; c[2] = 1.0;
    for (int i = 0; i < ch->dof; i++) {
        const double *J = ch->joints + HEAD * i;
        fixed_apply(J, p, a, b, c);
        double sign = J[12];
        for (int x = 0; x < 3; x++) {
            st->jw[i][x] = sign > 0.0 ? c[x] : -c[x];
            st->o[i][x] = p[x];
        }
        double th = (sign > 0.0 ? q[i] : -q[i]) + J[13];
        double co = cos(th), si = sin(th);
        for (int x = 0; x < 3; x++) {
            double ax = a[x], bx = b[x];
            a[x] = co * ax + si * bx;
            b[x] = co * bx - si * ax;
        }
    }
    fixed_apply(ch->tool, p, a, b, c);
}

/* ---------------------------------------------------------------- the task residual */

static double py_mod(double x, double y) { /* Python's float %: the sign of y */
    double r = fmod(x, y);
    if (r != 0.0 && ((r < 0.0) != (y < 0.0))) r += y;
    return r;
}

static double wrap(double angle) { return py_mod(angle + M_PI, 2.0 * M_PI) - M_PI; }

static double pitch_of(const State *st) {
    const double *a = st->a, *p = st->p;
    double rho = hypot(p[0], p[1]);
    double h = rho >= 1e-9 ? (a[0] * p[0] + a[1] * p[1]) / rho : hypot(a[0], a[1]);
    return atan2(a[2], h);
}

static void rotation_log(const double *g, const State *st, double *r) {
    /* the rotation vector [rad] of G R^T; about pi from the symmetric part */
    const double *cols[3] = {st->a, st->b, st->c};
    double E[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            E[i][j] = g[3 * i] * cols[0][j] + g[3 * i + 1] * cols[1][j] + g[3 * i + 2] * cols[2][j];
    double vx = E[2][1] - E[1][2], vy = E[0][2] - E[2][0], vz = E[1][0] - E[0][1];
    double s = 0.5 * sqrt(vx * vx + vy * vy + vz * vz);
    double c = 0.5 * (E[0][0] + E[1][1] + E[2][2] - 1.0);
    double theta = atan2(s, c);
    if (s > 1e-6 || c > 0.0) {
        double f = s < 1e-12 ? 0.5 : theta / (2.0 * s);
        r[0] = f * vx; r[1] = f * vy; r[2] = f * vz;
        return;
    }
    int k = 0;
    for (int i = 1; i < 3; i++)
        if (E[i][i] > E[k][k]) k = i;
    double col[3];
    for (int i = 0; i < 3; i++) col[i] = 0.5 * (E[i][k] + E[k][i]);
    col[k] = E[k][k] - c;
    double norm = sqrt(col[0] * col[0] + col[1] * col[1] + col[2] * col[2]);
    if (norm == 0.0) norm = 1.0;
    double sign = (col[0] * vx + col[1] * vy + col[2] * vz) < 0.0 ? -1.0 : 1.0;
    for (int i = 0; i < 3; i++) r[i] = sign * theta * col[i] / norm;
}

static void residual(const Task *t, const State *st, double w, Residual *res) {
    double e0 = t->p[0] - st->p[0], e1 = t->p[1] - st->p[1], e2 = t->p[2] - st->p[2];
    double pos2 = e0 * e0 + e1 * e1 + e2 * e2;
    res->e[0] = e0; res->e[1] = e1; res->e[2] = e2;
    res->pos = sqrt(pos2);
    if (t->mode == 1) {
        double d = wrap(t->pitch - pitch_of(st));
        double wd = w * d;
        res->e[3] = wd;
        res->m = 4;
        res->ang = fabs(d);
        res->cost = pos2 + wd * wd;
    } else if (t->mode == 2) {
        double r[3];
        rotation_log(t->R, st, r);
        for (int i = 0; i < 3; i++) res->e[3 + i] = w * r[i];
        res->m = 6;
        double ang2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
        res->ang = sqrt(ang2);
        res->cost = pos2 + w * w * ang2;
    } else {
        res->m = 3;
        res->ang = 0.0;
        res->cost = pos2;
    }
}

static int within(const Residual *r, const Task *t) {
    return r->pos <= t->tol_pos && r->ang <= t->tol_ang;
}

/* J by columns: J[j * m + i], row i of joint j */
static void task_jacobian(const Task *t, const State *st, int dof, double w, double *J) {
    int m = t->mode == 0 ? 3 : (t->mode == 1 ? 4 : 6);
    const double *p = st->p, *a = st->a;
    double rho = 0, h = 0, den = 0;
    if (t->mode == 1) {
        rho = fmax(hypot(p[0], p[1]), 1e-9);
        h = (a[0] * p[0] + a[1] * p[1]) / rho;
        den = fmax(a[2] * a[2] + h * h, 1e-300);
    }
    for (int j = 0; j < dof; j++) {
        const double *z = st->jw[j], *o = st->o[j];
        double dx = p[0] - o[0], dy = p[1] - o[1], dz = p[2] - o[2];
        double vx = z[1] * dz - z[2] * dy, vy = z[2] * dx - z[0] * dz, vz = z[0] * dy - z[1] * dx;
        double *col = J + j * m;
        col[0] = vx; col[1] = vy; col[2] = vz;
        if (t->mode == 1) {
            double wx = z[0], wy = z[1], wz = z[2];
            double dax = wy * a[2] - wz * a[1], day = wz * a[0] - wx * a[2];
            double daz = wx * a[1] - wy * a[0];
            double dh = (dax * p[0] + a[0] * vx + day * p[1] + a[1] * vy) / rho
                        - h * (p[0] * vx + p[1] * vy) / (rho * rho);
            col[3] = w * ((h * daz - a[2] * dh) / den);
        } else if (t->mode == 2) {
            col[3] = w * z[0]; col[4] = w * z[1]; col[5] = w * z[2];
        }
    }
}

/* ---------------------------------------------------------------- the damped step */

static void cholesky_solve(double *A, int n, double *x) {
    /* A (n x n, lower triangle used) overwritten by its factor; x: b in, solution out */
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < i; j++) {
            double s = A[i * n + j];
            for (int k = 0; k < j; k++) s -= A[i * n + k] * A[j * n + k];
            A[i * n + j] = s / A[j * n + j];
        }
        double s = A[i * n + i];
        for (int k = 0; k < i; k++) s -= A[i * n + k] * A[i * n + k];
        A[i * n + i] = sqrt(fmax(s, 1e-300));
    }
    for (int i = 0; i < n; i++) {
        double s = x[i];
        for (int k = 0; k < i; k++) s -= A[i * n + k] * x[k];
        x[i] = s / A[i * n + i];
    }
    for (int i = n - 1; i >= 0; i--) {
        double s = x[i];
        for (int k = i + 1; k < n; k++) s -= A[k * n + i] * x[k];
        x[i] = s / A[i * n + i];
    }
}

static void dls_step(const double *J, const double *e, int m, int dof, double lam,
                     const int *free, double *dq) {
    /* dq = argmin |J dq - e|^2 + lam |dq|^2 over the free joints (the others still) */
    int idx[MAXDOF], n = 0;
    for (int j = 0; j < dof; j++) {
        dq[j] = 0.0;
        if (free == NULL || free[j]) idx[n++] = j;
    }
    if (n == 0) return;
    if (m <= n) { /* dq = J^T (J J^T + lam I)^-1 e */
        double A[36], y[6];
        for (int r = 0; r < m; r++) {
            for (int c = 0; c <= r; c++) {
                double s = 0.0;
                for (int k = 0; k < n; k++) s += J[idx[k] * m + r] * J[idx[k] * m + c];
                A[r * m + c] = s + (r == c ? lam : 0.0);
            }
            y[r] = e[r];
        }
        cholesky_solve(A, m, y);
        for (int k = 0; k < n; k++) {
            double s = 0.0;
            for (int r = 0; r < m; r++) s += J[idx[k] * m + r] * y[r];
            dq[idx[k]] = s;
        }
        return;
    }
    double A[36], x[6]; /* n < m <= 6: dq = (J^T J + lam I)^-1 J^T e */
    for (int r = 0; r < n; r++) {
        const double *jr = J + idx[r] * m;
        for (int c = 0; c <= r; c++) {
            const double *jc = J + idx[c] * m;
            double s = 0.0;
            for (int i = 0; i < m; i++) s += jr[i] * jc[i];
            A[r * n + c] = s + (r == c ? lam : 0.0);
        }
        double s = 0.0;
        for (int i = 0; i < m; i++) s += jr[i] * e[i];
        x[r] = s;
    }
    cholesky_solve(A, n, x);
    for (int k = 0; k < n; k++) dq[idx[k]] = x[k];
}

static void take_step(const Chain *ch, const double *q, const double *J, const Residual *res,
                      double lam, double *trial) {
    int dof = ch->dof, m = res->m;
    double dq[MAXDOF];
    dls_step(J, res->e, m, dof, lam, NULL, dq);
    int at_limit = 0;
    for (int j = 0; j < dof; j++)
        if (q[j] <= ch->lower[j] || q[j] >= ch->upper[j]) at_limit = 1;
    if (at_limit) {
        int free[MAXDOF], all = 1;
        for (int j = 0; j < dof; j++) {
            free[j] = !((q[j] <= ch->lower[j] && dq[j] < 0.0) ||
                        (q[j] >= ch->upper[j] && dq[j] > 0.0));
            all &= free[j];
        }
        if (!all) dls_step(J, res->e, m, dof, lam, free, dq);
    }
    double biggest = 0.0;
    for (int j = 0; j < dof; j++) biggest = fmax(biggest, fabs(dq[j]));
    double k = biggest > MAX_STEP ? MAX_STEP / biggest : 1.0;
    for (int j = 0; j < dof; j++) {
        double v = q[j] + k * dq[j];
        trial[j] = v < ch->lower[j] ? ch->lower[j] : (v > ch->upper[j] ? ch->upper[j] : v);
    }
}

/* ---------------------------------------------------------------- the first joint's turn */

static void reject(const double *a, const double *z, double *out) {
    double k = a[0] * z[0] + a[1] * z[1] + a[2] * z[2];
    for (int x = 0; x < 3; x++) out[x] = a[x] - k * z[x];
}

static double dot(const double *a, const double *b) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static double z_cross(const double *z, const double *a, const double *b) { /* z . (a x b) */
    return z[0] * (a[1] * b[2] - a[2] * b[1]) + z[1] * (a[2] * b[0] - a[0] * b[2]) +
           z[2] * (a[0] * b[1] - a[1] * b[0]);
}

static double best_turn(const Task *t, const State *st, double w) {
    /* the turn of joint 0 [rad] that best aligns the tool with the task (see _turn.py) */
    const double *z = st->jw[0], *o = st->o[0], *p = st->p;
    double d[3], u[3], v[3], g[3];
    for (int x = 0; x < 3; x++) d[x] = p[x] - o[x];
    reject(d, z, u);
    for (int x = 0; x < 3; x++) d[x] = t->p[x] - p[x];
    reject(d, z, g);
    for (int x = 0; x < 3; x++) v[x] = u[x] + g[x];
    double num = z_cross(z, u, v), den = dot(u, v), w2 = w * w;
    const double *tool[3] = {st->a, st->b, st->c};
    double goal[3][3];
    int pairs = 0;
    if (t->mode == 2) {
        for (int k = 0; k < 3; k++)
            for (int x = 0; x < 3; x++) goal[k][x] = t->R[3 * x + k];
        pairs = 3;
    } else if (t->mode == 1) {
        const double *a = st->a;
        int on_axis = hypot(t->p[0], t->p[1]) < 1e-9;
        double hx = on_axis ? a[0] : t->p[0], hy = on_axis ? a[1] : t->p[1];
        double rho = hypot(hx, hy) + 1e-300, c = cos(t->pitch), s = sin(t->pitch);
        goal[0][0] = c * hx / rho; goal[0][1] = c * hy / rho; goal[0][2] = s;
        pairs = 1;
    }
    for (int k = 0; k < pairs; k++) {
        double a[3], b[3];
        reject(tool[k], z, a);
        reject(goal[k], z, b);
        num += w2 * z_cross(z, a, b);
        den += w2 * dot(a, b);
    }
    return atan2(num, den);
}

static void turn_first_joint(const Chain *ch, const Task *t, double *q, State *st,
                             Residual *res, int face_away) {
    /* joint 0 turned to its best angle if that lowers the cost; where that angle is
     * outside the limits: facing the opposite way (face_away) or at the nearer limit */
    double lo = ch->lower[0], hi = ch->upper[0];
    double turned[MAXDOF];
    memcpy(turned, q, sizeof(double) * ch->dof);
    turned[0] = q[0] + best_turn(t, st, ch->weight);
    int flip = !(lo <= turned[0] && turned[0] <= hi);
    if (flip && !face_away) {
        turned[0] = turned[0] > hi ? hi : lo;
        flip = 0;
    } else if (flip) {
        turned[0] += turned[0] > hi ? -M_PI : M_PI;
        if (!(lo <= turned[0] && turned[0] <= hi)) return;
    }
    State nst;
    Residual nres;
    forward(ch, turned, &nst);
    residual(t, &nst, ch->weight, &nres);
    if (flip || nres.cost < res->cost) {
        memcpy(q, turned, sizeof(double) * ch->dof);
        *st = nst;
        *res = nres;
    }
}

/* ---------------------------------------------------------------- runs and restarts */

static int lm_run(const Chain *ch, const Task *t, double *q, Residual *res, int face_away) {
    /* one run from q (changed in place); returns its iterations */
    State st, tst;
    Residual nres;
    double J[6 * MAXDOF], trial[MAXDOF];
    int dof = ch->dof, have_J = 0;
    forward(ch, q, &st);
    residual(t, &st, ch->weight, res);
    if (!within(res, t)) turn_first_joint(ch, t, q, &st, res, face_away);
    double mu = MU0, best = res->cost;
    int since = 0;
    for (int it = 0; it < RUN_ITERATIONS; it++) {
        if (within(res, t)) return it;
        if (!have_J) {
            task_jacobian(t, &st, dof, ch->weight, J);
            have_J = 1;
        }
        take_step(ch, q, J, res, mu * res->cost + 1e-12, trial);
        forward(ch, trial, &tst);
        residual(t, &tst, ch->weight, &nres);
        if (nres.cost < res->cost) {
            memcpy(q, trial, sizeof(double) * dof);
            st = tst;
            *res = nres;
            have_J = 0;
            mu = fmax(mu * MU_DOWN, 1e-4);
        } else {
            mu = mu * MU_UP;
        }
        if (res->cost < 0.95 * best) {
            best = res->cost;
            since = 0;
        } else if (++since >= STALL_ITERATIONS) {
            return it + 1;
        }
    }
    return RUN_ITERATIONS;
}

static double uniform01(uint64_t *s) { /* splitmix64, 53 bits */
    uint64_t z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z = z ^ (z >> 31);
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

static void sample(const Chain *ch, uint64_t *rng, double *q) {
    for (int j = 0; j < ch->dof; j++) {
        double lo = ch->lower[j], hi = ch->upper[j];
        q[j] = lo + (hi - lo) * uniform01(rng);
    }
}

static void restart_point(const Chain *ch, const Task *t, uint64_t *rng, int k, double *q) {
    /* odd k: the lowest-cost of CANDIDATES random joint vectors; even k: one sample */
    double cand[MAXDOF], cost = INFINITY;
    State st;
    Residual r;
    sample(ch, rng, q);
    if (k % 2 == 0) return;
    for (int i = 0; i < CANDIDATES; i++) {
        sample(ch, rng, cand);
        forward(ch, cand, &st);
        residual(t, &st, ch->weight, &r);
        if (r.cost < cost) {
            memcpy(q, cand, sizeof(double) * ch->dof);
            cost = r.cost;
        }
    }
}

typedef struct {
    int converged, iterations, restarts;
    double pos, ang, cost;
} Outcome;

static void solve(const Chain *ch, const Task *t, const double *seed, uint64_t rng_seed,
                  double *q_out, Outcome *out) {
    int dof = ch->dof;
    double q[MAXDOF];
    Residual res;
    for (int j = 0; j < dof; j++) {
        double v = seed[j];
        q[j] = v < ch->lower[j] ? ch->lower[j] : (v > ch->upper[j] ? ch->upper[j] : v);
    }
    int total = lm_run(ch, t, q, &res, 1);
    memcpy(q_out, q, sizeof(double) * dof);
    *out = (Outcome){within(&res, t), total, 0, res.pos, res.ang, res.cost};
    if (out->converged) return;
    double reach = sqrt(t->p[0] * t->p[0] + t->p[1] * t->p[1] + t->p[2] * t->p[2]);
    int restarts = reach > ch->reach ? 0 : MAX_RESTARTS;
    uint64_t rng = rng_seed;
    for (int k = 1; k <= restarts; k++) {
        restart_point(ch, t, &rng, k, q);
        total += lm_run(ch, t, q, &res, k % 2);
        int done = within(&res, t);
        if (done || res.cost < out->cost) {
            memcpy(q_out, q, sizeof(double) * dof);
            *out = (Outcome){done, total, k, res.pos, res.ang, res.cost};
        }
        if (done) break;
    }
    out->iterations = total;
}

/* ---------------------------------------------------------------- the Python interface */

static int read_chain(Py_buffer *buf, Chain *ch) {
    const double *d = buf->buf;
    Py_ssize_t n = buf->len / (Py_ssize_t)sizeof(double);
    if (n < 1 || d[0] < 1 || d[0] > MAXDOF) {
        PyErr_Format(PyExc_ValueError, "a packed chain has 1 to %d joints", MAXDOF);
        return -1;
    }
    ch->dof = (int)d[0];
    if (n != 1 + HEAD * ch->dof + 12 + 2 * ch->dof + 2) {
        PyErr_SetString(PyExc_ValueError, "packed chain of the wrong length");
        return -1;
    }
    ch->joints = d + 1;
    ch->tool = ch->joints + HEAD * ch->dof;
    ch->lower = ch->tool + 12;
    ch->upper = ch->lower + ch->dof;
    ch->reach = ch->upper[ch->dof];
    ch->weight = ch->upper[ch->dof + 1];
    return 0;
}

static int read_task(const double *d, int mode, double tol_pos, double tol_ang, Task *t) {
    if (mode < 0 || mode > 2) {
        PyErr_SetString(PyExc_ValueError, "mode is 0 (position), 1 (pitch) or 2 (pose)");
        return -1;
    }
    t->mode = mode;
    memcpy(t->p, d, 3 * sizeof(double));
    t->pitch = d[3];
    memcpy(t->R, d + 4, 9 * sizeof(double));
    t->tol_pos = tol_pos;
    t->tol_ang = tol_ang;
    return 0;
}

static int need(Py_buffer *b, Py_ssize_t doubles, const char *what) {
    if (b->len != doubles * (Py_ssize_t)sizeof(double)) {
        PyErr_Format(PyExc_ValueError, "%s must hold %zd float64", what, doubles);
        return -1;
    }
    return 0;
}

static PyObject *solve_one(PyObject *self, PyObject *args) {
    Py_buffer cb, tb;
    PyObject *seed_obj;
    int mode;
    double tol_pos, tol_ang;
    unsigned long long rng_seed;
    if (!PyArg_ParseTuple(args, "y*iy*OddK", &cb, &mode, &tb, &seed_obj, &tol_pos, &tol_ang,
                          &rng_seed))
        return NULL;
    Chain ch;
    Task t;
    double seed[MAXDOF], q[MAXDOF];
    PyObject *result = NULL, *fast = NULL;
    if (read_chain(&cb, &ch) < 0 || need(&tb, 13, "target") < 0 ||
        read_task(tb.buf, mode, tol_pos, tol_ang, &t) < 0)
        goto done;
    fast = PySequence_Fast(seed_obj, "seed must be a sequence of floats");
    if (fast == NULL) goto done;
    if (PySequence_Fast_GET_SIZE(fast) != ch.dof) {
        PyErr_SetString(PyExc_ValueError, "seed must have one float per joint");
        goto done;
    }
    for (int j = 0; j < ch.dof; j++) {
        seed[j] = PyFloat_AsDouble(PySequence_Fast_GET_ITEM(fast, j));
        if (seed[j] == -1.0 && PyErr_Occurred()) goto done;
    }
    Outcome out;
    solve(&ch, &t, seed, (uint64_t)rng_seed, q, &out);
    PyObject *qt = PyTuple_New(ch.dof);
    if (qt == NULL) goto done;
    for (int j = 0; j < ch.dof; j++) PyTuple_SET_ITEM(qt, j, PyFloat_FromDouble(q[j]));
    result = Py_BuildValue("(Niiiddd)", qt, out.converged, out.iterations, out.restarts, out.pos,
                           out.ang, out.cost);
done:
    Py_XDECREF(fast);
    PyBuffer_Release(&cb);
    PyBuffer_Release(&tb);
    return result;
}

static PyObject *solve_many(PyObject *self, PyObject *args) {
    Py_buffer cb, tb, sb, qb, ob;
    int mode;
    double tol_pos, tol_ang;
    unsigned long long rng_seed;
    if (!PyArg_ParseTuple(args, "y*iy*y*w*w*ddK", &cb, &mode, &tb, &sb, &qb, &ob, &tol_pos,
                          &tol_ang, &rng_seed))
        return NULL;
    PyObject *result = NULL;
    Chain ch;
    Task t;
    if (read_chain(&cb, &ch) < 0) goto done;
    Py_ssize_t n = tb.len / (Py_ssize_t)(13 * sizeof(double));
    if (need(&tb, 13 * n, "targets") < 0 || need(&sb, n * ch.dof, "seeds") < 0 ||
        need(&qb, n * ch.dof, "q") < 0 || need(&ob, 5 * n, "outcomes") < 0)
        goto done;
    if (mode < 0 || mode > 2) {
        PyErr_SetString(PyExc_ValueError, "mode is 0 (position), 1 (pitch) or 2 (pose)");
        goto done;
    }
    const double *targets = tb.buf, *seeds = sb.buf;
    double *q = qb.buf, *info = ob.buf;
    Py_BEGIN_ALLOW_THREADS
    for (Py_ssize_t i = 0; i < n; i++) {
        Outcome out;
        read_task(targets + 13 * i, mode, tol_pos, tol_ang, &t);
        solve(&ch, &t, seeds + ch.dof * i, (uint64_t)rng_seed, q + ch.dof * i, &out);
        double *o = info + 5 * i;
        o[0] = out.converged; o[1] = out.iterations; o[2] = out.restarts;
        o[3] = out.pos; o[4] = out.ang;
    }
    Py_END_ALLOW_THREADS
    result = Py_NewRef(Py_None);
done:
    PyBuffer_Release(&cb);
    PyBuffer_Release(&tb);
    PyBuffer_Release(&sb);
    PyBuffer_Release(&qb);
    PyBuffer_Release(&ob);
    return result;
}

static PyMethodDef methods[] = {
    {"solve_one", solve_one, METH_VARARGS,
     "solve_one(chain, mode, target, seed, tol_pos, tol_ang, rng_seed) -> (q, converged, "
     "iterations, restarts, position_error, angle_error, cost)"},
    {"solve_many", solve_many, METH_VARARGS,
     "solve_many(chain, mode, targets, seeds, q_out, outcomes_out, tol_pos, tol_ang, rng_seed)"},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_lmc", "armkit's LM IK solver, compiled (see _lmc.c).", -1, methods,
};

PyMODINIT_FUNC PyInit__lmc(void) { return PyModule_Create(&module); }
