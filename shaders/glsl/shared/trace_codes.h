// Termination reasons and step modes, shared by the CPU reference and the GLSL kernels.
// Reasons use VTK's vtkStreamTracer::ReasonForTermination values so ParaView users know them;
// VTK leaves the codes from 7 on to custom terminations.
#ifndef AMRSTREAM_SHARED_TRACE_CODES_H
#define AMRSTREAM_SHARED_TRACE_CODES_H

#define AMRSTREAM_REASON_RUNNING 0           // trace not finished yet
#define AMRSTREAM_REASON_OUT_OF_DOMAIN 1     // the next sample point left the data
#define AMRSTREAM_REASON_UNEXPECTED_VALUE 3  // invalid sample (no weight) or non-finite value
#define AMRSTREAM_REASON_MAX_LENGTH 4        // the next step would pass the length limit
#define AMRSTREAM_REASON_MAX_STEPS 5         // the step limit was reached
#define AMRSTREAM_REASON_STAGNATION 6        // speed below the terminal speed
#define AMRSTREAM_REASON_MAX_TIME 7          // |IntegrationTime| reached the time limit
#define AMRSTREAM_REASON_PERIODIC_WRAP 8  // written only: a polyline piece ends at a periodic face
#define AMRSTREAM_REASON_SERIES_END 9     // pathlines: the snapshot series ended

#define AMRSTREAM_STEP_CELL \
  0  // RK4 on dx/ds = w(x) v(x): step h in finest cell widths of the region
#define AMRSTREAM_STEP_TIME 1  // RK4 on dx/dt = v(x) with a fixed physical dt = h
#define AMRSTREAM_STEP_ARC 2   // RK4 on dx/ds = w(x) v/|v|: unit speed, step h in cell widths

// Integrators (--integrator); each has its step in include/<name>_step.glsl and its CPU twin in
// src/flow/line_steps.cpp.
#define AMRSTREAM_INTEGRATOR_RK4 0    // classic Runge-Kutta, fixed step (the paper's)
#define AMRSTREAM_INTEGRATOR_RK2 1    // midpoint rule, fixed step (VTK's vtkRungeKutta2)
#define AMRSTREAM_INTEGRATOR_EULER 2  // forward Euler, fixed step
#define AMRSTREAM_INTEGRATOR_RK45 3   // Dormand-Prince 5(4), adaptive step with error control

#endif
