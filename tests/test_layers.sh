# test_layers.sh: the #include lines of every source keep the declared order of folders
# (scripts/layers.sh; src/README, section 1): the core's rooms (contact, injury, risk, membrane
# < engine < modellang, impact) and the application's layers (base < case < cmd < ui < scale <
# main). Copies of the tree with one include that climbs (or crosses to a sibling room, or
# leaves the core for the application) are put through the same check first, so that the check
# is seen to fail.
. tests/lib.sh

# a copy of the sources with LINE appended to FILE; 0 if the check finds it (and names FILE)
caught() { # NAME FILE LINE
  rm -rf "$TMP/$1"
  mkdir -p "$TMP/$1"
  cp -R src include "$TMP/$1/"
  printf '%s\n' "$3" >>"$TMP/$1/$2"
  ! sh scripts/layers.sh "$TMP/$1" >"$TMP/$1.log" 2>&1 && grep -q "^$2: includes" "$TMP/$1.log"
}

check self_base_includes_cmd caught up1 src/app/base/parse.c '#include "../cmd/cmd.h"'
check self_case_includes_ui caught up2 src/app/case/state.c '#include "../ui/ui.h"'
check self_cmd_includes_scale caught up3 src/app/cmd/risk/cmd_risk.c '#include "../../scale/scale.h"'
check self_engine_includes_impact caught up4 src/core/engine/engine_run.c \
  '#include "../impact/impact_internal.h"'
check self_sibling_rooms caught up5 src/core/modellang/modellang.c \
  '#include "../impact/impact_internal.h"'
check self_core_includes_app caught up6 src/core/risk/rng.c '#include "../../app/base/base.h"'
check self_missing_header caught up7 src/app/ui/view.c '#include "nosuch.h"'

sh scripts/layers.sh . >"$TMP/tree.log" 2>&1
RC=$?
[ $RC -ne 0 ] && cat "$TMP/tree.log"
check tree_in_order [ $RC -eq 0 ]
finish
