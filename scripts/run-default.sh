#!/usr/bin/env bash
# The main job (`make run`): benchmark B2, Hertz 2D, with the shifted penalty on NP ranks (default 2).
cd "$(dirname "$0")/.." || exit 1
source scripts/env.sh
NP=${NP:-2}
echo "spcontact: B2 Hertz 2D with the shifted penalty on $NP ranks ($MPIEXEC -n $NP bin/spcontact -options_file input/hertz2d.opts -contact_monitor)"
$MPIEXEC -n "$NP" bin/spcontact -options_file input/hertz2d.opts -contact_monitor "$@"
rc=$?
echo "outputs: output/hertz2d.h5 + output/hertz2d.xmf (open the .xmf in ParaView), output/hertz2d.csv (Newton history), output/hertz2d_contact.csv (contact points)"
exit $rc
