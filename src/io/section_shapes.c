/* Section constants of the common closed shapes from their dimensions (docs/format.md,
 * "section"): the keys of a `section` line that give A, Iy, Iz, J at once.
 *   d=D              solid circle:  A = pi D^2 / 4, Iy = Iz = pi D^4 / 64, J = 2 Iy
 *   d=D t=T          tube (Di = D - 2T): A = pi (D^2 - Di^2) / 4, Iy = Iz =
 *                    pi (D^4 - Di^4) / 64, J = 2 Iy
 *   b=B h=H t=T      rectangular hollow (H along local z): A = B H - Bi Hi, Iy =
 *                    (B H^3 - Bi Hi^3) / 12, Iz = (H B^3 - Hi Bi^3) / 12 (Bi = B - 2T,
 *                    Hi = H - 2T), J = 2 T (B - T)^2 (H - T)^2 / (B + H - 2T) (Bredt)
 *   b=B h=H tf=F tw=W  I-section (flanges B x F, web W, depth H along local z): A =
 *                    2 B F + (H - 2F) W, Iy = (B H^3 - (B - W)(H - 2F)^3) / 12, Iz =
 *                    (2 F B^3 + (H - 2F) W^3) / 12, J = (2 B F^3 + (H - F) W^3) / 3
 * and the elastic section moduli W = I / c of the extreme fibre, c = D / 2, H / 2 (Wy)
 * or B / 2 (Wz). The keys A=, Iy=, Iz=, J=, Wy=, Wz= given on the same line replace the
 * values computed; an Iy= or Iz= given keeps the shape's extreme fibre for W. */
#include "io/parse.h"

#include <math.h>

#define PI 3.14159265358979323846

static void circle(double D, double T, ctn_section_spec *s)
{
    double Di = T > 0 ? D - 2 * T : 0;
    s->A = PI * (D * D - Di * Di) / 4;
    s->Iy = s->Iz = PI * (D * D * D * D - Di * Di * Di * Di) / 64;
    s->J = 2 * s->Iy;
    s->Wy = s->Wz = s->Iy / (D / 2);
}

static void box(double B, double H, double T, ctn_section_spec *s)
{
    double Bi = B - 2 * T, Hi = H - 2 * T;
    s->A = B * H - Bi * Hi;
    s->Iy = (B * H * H * H - Bi * Hi * Hi * Hi) / 12;
    s->Iz = (H * B * B * B - Hi * Bi * Bi * Bi) / 12;
    s->J = 2 * T * (B - T) * (B - T) * (H - T) * (H - T) / (B + H - 2 * T);
    s->Wy = s->Iy / (H / 2);
    s->Wz = s->Iz / (B / 2);
}

static void ibeam(double B, double H, double F, double W, ctn_section_spec *s)
{
    double hw = H - 2 * F;
    s->A = 2 * B * F + hw * W;
    s->Iy = (B * H * H * H - (B - W) * hw * hw * hw) / 12;
    s->Iz = (2 * F * B * B * B + hw * W * W * W) / 12;
    s->J = (2 * B * F * F * F + (H - F) * W * W * W) / 3;
    s->Wy = s->Iy / (H / 2);
    s->Wz = s->Iz / (B / 2);
}

/* The dimension keys present (v[k] = 0 if absent): the count of those given, or a
 * status in *rc; -2 - k if dimension k is not positive. */
static int dims(ctn_line *l, double v[6], int *rc)
{
    static const char *const key[6] = { "d", "t", "b", "h", "tf", "tw" };
    int n = 0;
    for (int k = 0; k < 6; k++) {
        v[k] = 0;
        if (!ctn_parse_key(l, 2, key[k])) continue;
        if ((*rc = ctn_parse_key_num(l, 2, key[k], 1, &v[k]))) return -1;
        if (!(v[k] > 0)) return -2 - k;
        n++;
    }
    return n;
}

int ctn_parse_section_shape(ctn_line *l, ctn_section_spec *s, int *shaped)
{
    static const char *const key[6] = { "d", "t", "b", "h", "tf", "tw" };
    double v[6];
    const char *name = l->tok[1];
    int rc = CTN_OK, n = dims(l, v, &rc);
    *shaped = n > 0;
    if (n == -1) return rc;
    if (n < -1) return ctn_parse_error(l, "section %s: %s must be positive (found %g)", name, key[-n - 2], v[-n - 2]);
    if (!n) return CTN_OK;
    int d = v[0] > 0, t = v[1] > 0, bh = v[2] > 0 && v[3] > 0, fw = v[4] > 0 && v[5] > 0;
    if (d && n == 1 + t) {
        if (t && !(2 * v[1] < v[0]))
            return ctn_parse_error(l, "section %s: a tube's wall t=%g must be thinner than half its diameter d=%g", name, v[1], v[0]);
        circle(v[0], v[1], s);
    } else if (bh && t && n == 3) {
        if (!(2 * v[1] < v[2] && 2 * v[1] < v[3]))
            return ctn_parse_error(l, "section %s: a box's wall t=%g must be thinner than half its sides b=%g, h=%g", name, v[1], v[2], v[3]);
        box(v[2], v[3], v[1], s);
    } else if (bh && fw && n == 4) {
        if (!(2 * v[4] < v[3] && v[5] <= v[2]))
            return ctn_parse_error(l, "section %s: an I-section needs 2 tf < h and tw <= b (found b=%g h=%g tf=%g tw=%g)", name,
                                   v[2], v[3], v[4], v[5]);
        ibeam(v[2], v[3], v[4], v[5], s);
    } else {
        return ctn_parse_error(l, "section %s: the dimensions give one shape: d= (solid circle), d= t= (tube), b= h= t= "
                               "(rectangular hollow) or b= h= tf= tw= (I-section)", name);
    }
    return isfinite(s->A) && isfinite(s->Iy) && isfinite(s->Iz) && isfinite(s->J)
               ? CTN_OK
               : ctn_parse_error(l, "section %s: its dimensions overflow", name);
}

void ctn_parse_section_moduli(ctn_line *l, const double I[2], const double W[2], ctn_section_spec *s)
{
    double *Is[2] = { &s->Iy, &s->Iz }, *Ws[2] = { &s->Wy, &s->Wz };
    static const char *const wkey[2] = { "Wy", "Wz" };
    for (int k = 0; k < 2; k++)       /* an I= given: the same extreme fibre, I / c */
        if (!ctn_parse_key(l, 2, wkey[k]) && *Is[k] != I[k] && I[k] > 0) *Ws[k] = *Is[k] * (W[k] / I[k]);
}
