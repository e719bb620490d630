/* use_cli_heap(): the catena command's process-wide memory settings (ctn_process_heap,
 * catena/core.h), for a program that asks for them. The package never calls it: a
 * library leaves the process as it found it, and these settings belong to the whole
 * process (every allocation of every module), cannot be undone, and trade memory
 * returned to the system for fewer page faults in large solves. */
#include "pycatena.h"

PyObject *pyctn_use_cli_heap(PyObject *module, PyObject *noargs)
{
    (void)module;
    (void)noargs;
    return PyBool_FromLong(ctn_process_heap());
}
