/* Internal: the dynamics analysis's working state, shared by dynamics.c (the driver),
 * dyn_implicit.c (a step of the generalized-alpha family), dyn_central.c (explicit
 * central differences) and dyn_record.c (the histories and the energy balance).
 * Vectors: "state" ones (ns) hold every DOF, d; "ndof" ones the free DOFs, v and a. */
#ifndef CTN_ANALYSIS_DYNAMICS_H
#define CTN_ANALYSIS_DYNAMICS_H

#include "problem/problem.h"

typedef struct ctn_dyn {
    ctn_problem *p;
    ctn_solution *s;
    const ctn_dynamics_options *o;
    ctn_dynamics_summary sum;
    double am, af, gamma, beta;   /* the method's parameters */
    double *Mx;                   /* nnz: mass, the tangent's pattern */
    int *mcol, *mrow;             /* M's own upper pattern: its nonzeros only (ndof + 1, mnz) */
    int *mslot;                   /* mnz: where each of them is in the tangent's values */
    double *mval;                 /* mnz: their values (M x by it: 3 to 5 times fewer entries) */
    double *Cx;                   /* nnz: Rayleigh damping a M + b K_0, NULL without */
    double *diag;                 /* ndof: the lumped mass diagonal */
    double *d0, *d1;              /* state: at t_n, and the step's iterate at t_n+1 */
    double *v0, *a0, *v1, *a1;    /* ndof: velocities and accelerations */
    double *r0, *r1;              /* ndof: f_ext - f_int at t_n, at the iterate */
    double *R, *w, *w2;           /* ndof: the step's residual, scratch */
    double *ework;                /* element scratch (records of element forces) */
    double *fe0;                  /* state: f_ext at t_n (the work of the loads) */
    double ek, U, W, D;           /* energies at t_n: kinetic, strain, work, damping */
    double e0;                    /* E_k + U at t = 0 */
    double escale;                /* the largest E_k + U + |W| + D so far */
    double emax;                  /* the largest |E_k + U - W + D - e0| so far */
    double U1;                    /* strain energy at the last residual */
    int lumped;                   /* the mass matrix is the lumped one */
    unsigned char *severed;       /* per model removal: applied */
    int every;                    /* a row every this many steps (output_every) */
    double *react, *vs, *as;      /* state: reactions, the velocity and acceleration of every
                                     DOF (dyn_output.c; NULL when no reaction is asked) */
    size_t nsup;                  /* the support elements (with a fixed DOF): */
    size_t *sup_e, *sup_off;      /* their indices, the offsets of their packed blocks in */
    double *sup_M, *sup_K;        /* their mass and start tangent (sup_K: beta > 0 only) */
    size_t *sup_idx;              /* maxdof: an element's state indices */
    double *fsup;                 /* ndof: M_fs a_s + C_fs v_s of the moving supports over the
                                     step (NULL: no support moves) */
    size_t mr;                    /* modal damping (dyn_modal.c): its modes r (0: none), */
    double *mPhi, *mU, *mY;       /* ndof x r: Phi, U = M Phi, Y = A^-1 U (A the factored */
    double *mE;                   /* effective tangent); r: 2 zeta_i omega_i */
    double *mS;                   /* r x r: S = I + c2 E U^T Y, LU-factored (pivots mpiv) */
    size_t *mpiv;
    double mc2;                   /* c2 of the factored S */
    double *mG;                   /* r: 2 zeta_i / omega_i (E Omega^-2: a moving support's */
    double *mg;                   /* ndof: K_fs v_s, the support velocity's stiffness force) */
    size_t nwind;                 /* relative wind (dyn_wind.c): elements under a wind, */
    size_t *welem;                /* their indices, */
    double *wk, *wvel, *wD;       /* rho cd d / 2, the wind's velocity (3), the last block */
    double *wf, *wf0;             /* state: the drag at the last evaluation, at t_n */
    double *wv;                   /* state: every DOF's velocity (scratch) */
    double t1;                    /* the end time of the step being taken */
    struct ctn_dyn_rot *rot;      /* finite rotations' inertia (dyn_rot.c), NULL without */
    double *fh0;                  /* state: the follower loads at t_n (NULL without) */
} ctn_dyn;

/* A model error at the `dynamics` line (or without a place, from the API) (dyn_check.c). */
int ctn_dyn_error(const ctn_problem *p, const ctn_dynamics_options *o, const char *msg);
/* dyn_start.c: the method's am, af, gamma, beta; the held loads and d0; the start (r0,
 * K_0, M on its own pattern, C, a0, the energies, the explicit stable step, the first
 * row); a0 = M^-1 (f_ext - f_int(d0) - C v0) (over the lumped diagonal where M is
 * singular, or lumped). */
void ctn_dyn_method_params(ctn_dyn *dy);
void ctn_dyn_start_loads(ctn_dyn *dy);
int ctn_dyn_start(ctn_dyn *dy);
int ctn_dyn_acceleration(ctn_dyn *dy);
/* dyn_removal.c: the removals due at t applied (the state rebalanced), the next one after
 * t (INFINITY if none), the severed elements restored. */
int ctn_dyn_apply_removals(ctn_dyn *dy, double t);
double ctn_dyn_next_removal(const ctn_dyn *dy, double t);
void ctn_dyn_restore_removals(ctn_dyn *dy);

/* The loads and the fixed DOFs of d at time t: the held ones (p->f1, p->p1) and the
 * model's forces and support motions times their functions of time (p->fext, d). */
void ctn_dyn_set_time(ctn_dyn *dy, double t, double *d);

/* One implicit step of size h from (d0, v0, a0) into (d1, v1, a1); *ok = 0 when it did
 * not converge (maxit, a collapsed element, an indefinite effective tangent). */
int ctn_dyn_implicit_step(ctn_dyn *dy, double h, int *ok);
/* The central differences: the stable step of the mesh at d0 (K_T there, Gershgorin's
 * bound on the largest eigenvalue of M^-1 K over the lumped mass) into sum.dt_stable. */
int ctn_dyn_stable_step(ctn_dyn *dy);
/* One explicit step of size h; *ok = 0 when an element collapsed. */
int ctn_dyn_central_step(ctn_dyn *dy, double h, int *ok);

/* f_ext - f_int at d (state) into r (ndof), the strain energy into dy->U1, K_T into p->Kx
 * if with_K; *valid as ctn_problem_residual's. */
int ctn_dyn_residual(ctn_dyn *dy, const double *d, int with_K, double *r, int *valid);
/* y = M x, y = C x (ndof; C: y = 0 without damping). */
void ctn_dyn_mass(const ctn_dyn *dy, const double *x, double *y);
void ctn_dyn_damp(const ctn_dyn *dy, const double *x, double *y);
/* Accept the step into t_n: the energies advanced over it (work, dissipation), the
 * state moved (d1, v1, a1, r -> d0, v0, a0, r0). */
void ctn_dyn_accept(ctn_dyn *dy, double h, const double *r1);

/* dyn_output.c: the velocity and acceleration of every DOF (state layout) at t: the free
 * ones' vq, aq (ndof), the fixed ones' from their support motion's function (as NULL:
 * none); the support elements' mass and K_0 kept when reactions or frames are asked
 * (after K_0 is at d0); the reactions f_int + M a + C v - f_ext at d0 into dy->react
 * (the elements' axial forces into force, ne, unless NULL); a frame of the state at t. */
void ctn_dyn_rates(const ctn_dyn *dy, double t, const double *vq, const double *aq, double *vs, double *as);
int ctn_dyn_output_begin(ctn_dyn *dy);
int ctn_dyn_reactions(ctn_dyn *dy, double t, double *force);
int ctn_dyn_keep_frame(ctn_dyn *dy, double t);
/* The moving supports' inertia and damping on the free DOFs over a step from t0 to t1,
 * M_fs a_s + C_fs v_s with a_s, v_s weighted wa, wv at t1 (1 - wa, 1 - wv at t0), into
 * dy->fsup (nothing when no support moves). */
void ctn_dyn_support_force(ctn_dyn *dy, double t0, double t1, double wa, double wv);
/* g (ndof) = K_fs v_s with the fixed DOFs' velocities vs (state layout, 0 on the free
 * DOFs), K the support elements' start tangent (modal damping only). */
void ctn_dyn_support_stiffness(ctn_dyn *dy, const double *vs, double *g);

/* dyn_modal.c: modal damping's modes about d0 (after M's own pattern and before a0);
 * y += C_m x (ndof); w = Phi E U^T v (ndof: the modal damping force is M w, for the
 * reactions); after A = K_T + c1 M + c2 C_R is factored, Y and S for c2 (*ok = 0 when S is
 * singular); x = A^-1 b corrected into (A + c2 C_m)^-1 b. Each a no-op without it. */
int ctn_dyn_modal_setup(ctn_dyn *dy);
void ctn_dyn_modal_damp(const ctn_dyn *dy, const double *x, double *y);
void ctn_dyn_modal_velocity(const ctn_dyn *dy, const double *v, const double *g, double *w);
/* A moving support under modal damping: the modes damp the free DOFs' velocity relative
 * to the quasi-static one, v_qs = -K^-1 K_fs v_s, i.e. C_m (v - v_qs) = C_m v + C_m K^-1
 * g with g = K_fs v_s; C_m K^-1 = U E Omega^-2 Phi^T (K Phi = M Phi Omega^2, K and the
 * modes the start's), so y += U diag(2 zeta_i / omega_i) Phi^T g (ndof). The same in
 * modal_velocity: w = Phi E (U^T v + Omega^-2 Phi^T g) (g NULL: none). */
void ctn_dyn_modal_support(const ctn_dyn *dy, const double *g, double *y);
int ctn_dyn_modal_factor(ctn_dyn *dy, double c2, int *ok);
void ctn_dyn_modal_correct(const ctn_dyn *dy, double *x);
/* dyn_wind.c: the winds a dynamics can take (CTN_ERR_MODEL otherwise); the elements under
 * them; their drag at positions d (state) and free velocities v (ndof; a moving support's
 * from its function at t) added into r (ndof), kept in dy->wf; c2 times its velocity
 * derivative's blocks added into the effective tangent p->Kx. */
int ctn_dyn_wind_check(const ctn_problem *p, const ctn_dynamics_options *o);
int ctn_dyn_wind_setup(ctn_dyn *dy);
void ctn_dyn_wind(ctn_dyn *dy, const double *d, const double *v, double t, double *r);
void ctn_dyn_wind_tangent(ctn_dyn *dy, double c2);

/* dyn_rot.c: the nodes with free rotations, their rotary inertia J (material frame) from
 * the families' lumped mass, M's rotation entries zeroed (before M's own pattern; a no-op
 * without rotations); the material W1, A1 of the step's iterate d1 (Newmark on the
 * rotation increment log(R0^T R1)) and their inertia moments I1 = R1 (J A1 + W1 x J W1)
 * (also into v1, a1 at their equations); y -= (1 - am) I1 + am I0 (returns the sum of
 * squares of what it took); c1 R1 J R1^T into the tangent p->Kx; the step accepted (the
 * rotational kinetic energy at t_n+1 returned); the work of forces f0, f1 (state) over
 * the spatial rotation increments of the step; c R0 J R0^T into dy->Mx (at d0); from the
 * spatial accelerations a (ndof) at the start, A0 = R0^T a (a takes A0), W0 = 0. */
int ctn_dyn_rot_setup(ctn_dyn *dy);
void ctn_dyn_rot_free(ctn_dyn *dy);
void ctn_dyn_rot_kinematics(ctn_dyn *dy, double h);
double ctn_dyn_rot_residual(const ctn_dyn *dy, double *y);
void ctn_dyn_rot_tangent(ctn_dyn *dy, double c1);
double ctn_dyn_rot_accept(ctn_dyn *dy);
double ctn_dyn_rot_work(const ctn_dyn *dy, const double *f0, const double *f1);
void ctn_dyn_rot_mass_add(ctn_dyn *dy, double scale);
void ctn_dyn_rot_start(ctn_dyn *dy, double *a);
/* The rotary inertia's and its alpha damping's moments at t_n, R0 (J A0 + W0 x J W0) +
 * alpha R0 J W0, added into react (state) at the fixed rotations of the nodes that turn. */
void ctn_dyn_rot_reactions(const ctn_dyn *dy, double *react);

/* dyn_rot_damp.c: damping on the spatial velocities (a rotation's w = R W, R at the state
 * d of that velocity): vs (ndof) = v with its rotations' W turned to R(d) W (vs may be v);
 * y += alpha R(d) J W at the rotations' equations (W from v); y += R(d) J R(d)^T x there;
 * y = the damping force of v at d, C v_s + alpha R J W (vs: v_s, scratch), as
 * ctn_dyn_damp without rotations. */
void ctn_dyn_rot_spatial(const ctn_dyn *dy, const double *d, const double *v, double *vs);
void ctn_dyn_rot_damp_mass(const ctn_dyn *dy, const double *d, const double *v, double alpha, double *y);
void ctn_dyn_rot_mass_mult(const ctn_dyn *dy, const double *d, const double *x, double *y);
void ctn_dyn_damp_at(const ctn_dyn *dy, const double *d, const double *v, double *vs, double *y);

/* dyn_rot_central.c: the central differences' rotations: dy->diag at the rotations'
 * equations = each node's least rotary inertia (the stable step's); the spins of the
 * step R0 h W(n+1/2) into w (ndof, at the rotations' equations; W(n+1/2) kept); from the
 * spatial forces f (ndof: residual less damping) at d1, W1 and A1 (also into v1, a1);
 * 0 when W1's fixed point did not converge. */
void ctn_dyn_rot_stable_diag(ctn_dyn *dy);
void ctn_dyn_rot_central_turn(ctn_dyn *dy, double h, double *w);
int ctn_dyn_rot_central_rates(ctn_dyn *dy, double h, const double *f);

/* dyn_rot_exact.c: the consistent tangent of the rotations' inertia and damping (implicit
 * methods, nodes with three composed rotations; after the damping is set up); its
 * blocks at the iterate d1 (after the kinematics); x = (A + B)^-1 b, A the factored
 * effective tangent (A^-1 alone without rotations). */
int ctn_dyn_exact_setup(ctn_dyn *dy);
void ctn_dyn_exact_blocks(ctn_dyn *dy, double h);
int ctn_dyn_exact_solve(ctn_dyn *dy, const double *b, double *x);

/* Whether the analysis has damping (Rayleigh's or modal). */
static inline int ctn_dyn_damped(const ctn_dyn *dy) { return dy->Cx != NULL || dy->mr > 0; }

/* The result's columns (the model's records) and its first row (t = 0); a row at t. */
int ctn_dyn_record_begin(ctn_dyn *dy);
/* The directions record r takes (a reaction's 0: its node's fixed ones). */
unsigned ctn_dyn_record_dofs(const ctn_model *m, const ctn_record *r);
int ctn_dyn_record_row(ctn_dyn *dy, double t);

#endif
