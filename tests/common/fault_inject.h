/* The writers' fault injector (fault_inject.c), an LD_PRELOAD library: the k-th write (and every
 * later one: a full disk stays full), or the k-th fsync, or the k-th close of a regular file below
 * one folder fails (ENOSPC for writes, EIO for the others); writes and closes count on descriptors
 * opened for writing, fsync on any. Descriptors 0-2, other files and anything that is not a
 * regular file are neither counted nor failed. Configured by the
 * environment when a process starts, or by tl_fault_arm (found with dlsym) in a test that runs
 * with the library preloaded. */
#ifndef TL_FAULT_INJECT_H
#define TL_FAULT_INJECT_H

#define TL_FAULT_ENV_DIR "TL_FAULT_DIR"       /* absolute folder whose files count; unset: nothing */
#define TL_FAULT_ENV_CALL "TL_FAULT_CALL"     /* write (default), short (the k-th write stores half
                                                 its bytes, later ones fail), fsync or close */
#define TL_FAULT_ENV_AT "TL_FAULT_AT"         /* k >= 1; 0 or unset: count only */
#define TL_FAULT_ENV_REPORT "TL_FAULT_REPORT" /* a file that gets "PID write N fsync N close N" at exit */
#define TL_FAULT_ENV_WITHOUT "TL_FAULT_WITHOUT" /* "tmpfile": open(O_TMPFILE) fails (EOPNOTSUPP);
                                                   "link": linkat fails (ENOENT); both may be named */

/* Re-arms the injector of this process (the counts restart): `dir` NULL disarms it. */
typedef void (*tl_fault_arm_fn)(const char *dir, const char *call, unsigned long at);
/* tl_fault_without: what the process is to lack from now on ("tmpfile", "link", both, or NULL). */
typedef void (*tl_fault_without_fn)(const char *what);
/* The calls of one kind ("write" = "short", "fsync", "close") counted since the last arming. */
typedef unsigned long (*tl_fault_seen_fn)(const char *call);

#endif
