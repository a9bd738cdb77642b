# Shared launcher settings for every spcontact script and test. Source it; override by exporting first.
#   MPIEXEC  the MPI launcher, with the flags this machine needs (root, oversubscription)
#   PYTHON   the interpreter that has Debian's h5py/numpy/matplotlib
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1}
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
# Open MPI warns about missing high-speed transports on a plain machine; keep runs quiet.
export OMPI_MCA_btl=${OMPI_MCA_btl:-self,vader,tcp}
export OMPI_MCA_btl_base_warn_component_unused=${OMPI_MCA_btl_base_warn_component_unused:-0}
# more ranks than cores (tests use 3 ranks on 2 cores): idle ranks yield instead of spinning
export OMPI_MCA_mpi_yield_when_idle=${OMPI_MCA_mpi_yield_when_idle:-1}
MPIEXEC=${MPIEXEC:-"mpiexec --oversubscribe --bind-to none"}
PYTHON=${PYTHON:-/usr/bin/python3}
export MPIEXEC PYTHON
