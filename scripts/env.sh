# Shared launcher settings for every spcontact script and test. Source it; override by exporting first.
#   MPIEXEC  the MPI launcher, with the flags this machine needs (root, oversubscription)
#   PYTHON   the interpreter that has Debian's h5py/numpy/matplotlib
export OMPI_ALLOW_RUN_AS_ROOT=${OMPI_ALLOW_RUN_AS_ROOT:-1}
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=${OMPI_ALLOW_RUN_AS_ROOT_CONFIRM:-1}
# Open MPI warns about missing high-speed transports on a plain machine; keep runs quiet.
export OMPI_MCA_btl=${OMPI_MCA_btl:-self,vader,tcp}
export OMPI_MCA_btl_base_warn_component_unused=${OMPI_MCA_btl_base_warn_component_unused:-0}
# Start-up: Open MPI's default UCX messaging layer probes for network devices in MPI_Init, which
# costs 0.23 s of the 0.42 s a one-rank MPI_Init takes here (measured: 0.42 s -> 0.16 s). On one
# node the ob1 layer over shared memory (vader) is the standard choice; on a cluster with a fast
# network export OMPI_MCA_pml=ucx (or unset these) before sourcing this file.
export OMPI_MCA_pml=${OMPI_MCA_pml:-ob1}
export OMPI_MCA_osc=${OMPI_MCA_osc:-^ucx}
export OMPI_MCA_mtl=${OMPI_MCA_mtl:-^ofi,psm,psm2}
# more ranks than cores (tests use 3 ranks on 2 cores): idle ranks yield instead of spinning
export OMPI_MCA_mpi_yield_when_idle=${OMPI_MCA_mpi_yield_when_idle:-1}
MPIEXEC=${MPIEXEC:-"mpiexec --oversubscribe --bind-to none"}
PYTHON=${PYTHON:-/usr/bin/python3}
export MPIEXEC PYTHON
