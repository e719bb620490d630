/* The chord of a hanging member from the force at its middle (the `hang` op of
 * element.h): a straight bar, and an elastic catenary (Irvine) under its weight. */
#ifndef CTN_ELEMENT_HANG_LAW_H
#define CTN_ELEMENT_HANG_LAW_H

/* A bar of unstressed length l0 and rigidity EA (engineering strain): v = l0 (1 + |S| /
 * EA) S / |S|, phi = l0 |S| + l0 |S|^2 / (2 EA), H its Hessian. NAN if |S| or EA is 0. */
double ctn_hang_bar(double l0, double EA, const double S[3], double v[3], double H[9]);

/* An elastic catenary of unstressed length l0, rigidity EA and total weight W along -up
 * (up: unit, opposite gravity): with N(s) = S - (W / l0) (s - l0 / 2) up the force along
 * its unstressed arc s, v = int_0^l0 (N / |N| + N / EA) ds, phi = int (|N| + |N|^2 /
 * (2 EA)) ds in closed form; H the bar's at S (a positive definite stand-in). A weight
 * below 1e-9 |S| is a bar's. NAN where N vanishes across the member's whole length or H
 * is singular. */
double ctn_hang_catenary(double l0, double EA, double W, const double up[3], const double S[3], double v[3],
                         double H[9]);

#endif
