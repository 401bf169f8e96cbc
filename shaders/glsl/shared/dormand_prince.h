// The Dormand-Prince 5(4) tableau (Dormand and Prince 1980) as float literals, and the step
// controller's table, shared by the CPU step (src/flow/line_steps.cpp) and the GLSL one
// (include/rk45_step.glsl) so that both round the same constants. Each literal is the float
// nearest the exact fraction in the comment.
#ifndef AMRSTREAM_SHARED_DORMAND_PRINCE_H
#define AMRSTREAM_SHARED_DORMAND_PRINCE_H

#define AMRSTREAM_DP_A21 0.2f          // 1/5
#define AMRSTREAM_DP_A31 0.075f        // 3/40
#define AMRSTREAM_DP_A32 0.225f        // 9/40
#define AMRSTREAM_DP_A41 0.9777778f    // 44/45
#define AMRSTREAM_DP_A42 -3.7333333f   // -56/15
#define AMRSTREAM_DP_A43 3.5555556f    // 32/9
#define AMRSTREAM_DP_A51 2.9525986f    // 19372/6561
#define AMRSTREAM_DP_A52 -11.595794f   // -25360/2187
#define AMRSTREAM_DP_A53 9.822893f     // 64448/6561
#define AMRSTREAM_DP_A54 -0.29080933f  // -212/729
#define AMRSTREAM_DP_A61 2.8462753f    // 9017/3168
#define AMRSTREAM_DP_A62 -10.757576f   // -355/33
#define AMRSTREAM_DP_A63 8.906423f     // 46732/5247
#define AMRSTREAM_DP_A64 0.2784091f    // 49/176
#define AMRSTREAM_DP_A65 -0.27353132f  // -5103/18656
// The fifth-order weights, which advance the line (b2 = b7 = 0).
#define AMRSTREAM_DP_B1 0.091145836f  // 35/384
#define AMRSTREAM_DP_B3 0.4492363f    // 500/1113
#define AMRSTREAM_DP_B4 0.6510417f    // 125/192
#define AMRSTREAM_DP_B5 -0.3223762f   // -2187/6784
#define AMRSTREAM_DP_B6 0.13095239f   // 11/84
// Fifth- minus fourth-order weights: the error estimate (e2 = 0; e7 weighs the end point's
// stage, which is the next step's first).
#define AMRSTREAM_DP_E1 0.0012326388f   // 71/57600
#define AMRSTREAM_DP_E3 -0.0042527704f  // -71/16695
#define AMRSTREAM_DP_E4 0.036979165f    // 71/1920
#define AMRSTREAM_DP_E5 -0.0508638f     // -17253/339200
#define AMRSTREAM_DP_E6 0.041904762f    // 22/525
#define AMRSTREAM_DP_E7 -0.025f         // -1/40

// 2^(-r/10) for r = 0..9: the controller scales steps by 0.9 (tol/err)^(1/5), from the binary
// exponents of err² and tol² alone, so that host and device take the same decisions.
#define AMRSTREAM_HALF_TENTHS                                                              \
  1.0f, 0.933033f, 0.8705506f, 0.8122524f, 0.7578583f, 0.70710677f, 0.659754f, 0.6155722f, \
      0.57434916f, 0.5358867f
#define AMRSTREAM_RK45_MAX_ATTEMPTS 32  // tries of one step before it is taken regardless
// A step may move one finest cell of its region and 0.1 % (squared: 1.002): in arc mode a step
// of h = 1 moves exactly one cell, which rounding would put on either side of the bound.
#define AMRSTREAM_RK45_CAP_SQUARED_MARGIN 1.002f
// The displacement's binary exponent is taken of its square times sqrt(2), so that a step of a
// power-of-two fraction of a cell (as the first, h = 0.25 in arc mode) lies mid-binade, not on
// a boundary that rounding would put it on either side of.
#define AMRSTREAM_RK45_BINADE_SHIFT 1.4142135f

#endif
