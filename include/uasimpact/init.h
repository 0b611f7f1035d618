/* init.h: what the host of the library asks of it once, before use.
 *
 * Every core function reports failure by its return value (and a message where it has one).
 * GSL, which the core uses for the descent's integration and some distributions, has a
 * process-wide error handler whose default prints a message and aborts the program; the core
 * never changes it on its own (it belongs to the process, and another user of GSL in the same
 * program may rely on it). A host that wants GSL's failures inside the core to come back as the
 * core's return codes asks for urINIT_GSL_CODES; the workbench does (ura_init).
 */
#ifndef UASIMPACT_INIT_H
#define UASIMPACT_INIT_H

#ifdef __cplusplus
extern "C" {
#endif

#define urINIT_GSL_CODES 1u /* turn GSL's abort handler off: its errors become codes */

/* apply the options (bits above); 0, or -1 for an unknown bit (then nothing is changed) */
int ur_init(unsigned flags);

#ifdef __cplusplus
}
#endif
#endif
