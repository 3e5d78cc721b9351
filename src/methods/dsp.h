/* The paper's four Discrete Suslov Problems as stepper types, by name (for the registry table,
 * registry.c) and as pointers, like GSL's gsl_odeiv2_step_rk4. */
#ifndef SUS_STEP_DSP_H
#define SUS_STEP_DSP_H

#include "stepper.h"

#ifdef __cplusplus
extern "C" {
#endif

extern const sus_stepper_type sus_step_euler_type, sus_step_rk4_type, sus_step_midpoint_type,
    sus_step_variational_type;
extern const sus_stepper_type *const sus_step_euler;
extern const sus_stepper_type *const sus_step_rk4;
extern const sus_stepper_type *const sus_step_midpoint;
extern const sus_stepper_type *const sus_step_variational;

#ifdef __cplusplus
}
#endif

#endif
