/* units.h — physical constants (SI) and unit conversions used at the edges.
 *
 * Each constant carries its unit in a comment.  Conversions to and from
 * non-SI units (inch, mAh, degC, g) happen only where mission values enter
 * the engine or results leave it.
 */
#ifndef AEROEVAL_UNITS_H
#define AEROEVAL_UNITS_H

#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define G0_M_S2          9.80665     /* standard gravity, m / s^2 */
#define R_AIR_J_KGK      287.058     /* specific gas constant of air, J / (kg K) */
#define GAMMA_AIR        1.4         /* ratio of specific heats of air, - */
#define ISA_P0_PA        101325.0    /* sea-level pressure, Pa */
#define ISA_T0_K         288.15      /* sea-level temperature, K */
#define ISA_LAPSE_K_M    0.0065      /* tropospheric lapse rate, K / m */
#define ISA_H11_M        11000.0     /* tropopause altitude, m */
#define ISA_T11_K        216.65      /* stratosphere temperature, K */
#define ISA_HMAX_M       20000.0     /* top of the modelled atmosphere, m */
#define RHO_SL_KG_M3     1.225       /* sea-level density, kg / m^3 */
#define KELVIN_OFFSET    273.15      /* degC -> K */

#define M_PER_IN         0.0254      /* inch -> m */
#define S_PER_MIN        60.0        /* minute -> s */
#define S_PER_H          3600.0      /* hour -> s */

static inline double in_to_m(double in) { return in * M_PER_IN; }
static inline double m_to_in(double m) { return m / M_PER_IN; }
static inline double c_to_k(double c) { return c + KELVIN_OFFSET; }
static inline double k_to_c(double k) { return k - KELVIN_OFFSET; }
static inline double mah_to_ah(double mah) { return mah / 1000.0; }

#endif
