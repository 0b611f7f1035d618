#!/bin/sh
# test_quad_bag.sh: any drone may declare airbags (issue 32): the example quadcopter
# (sessions/quad/quad.urm) with a membrane bag on its top compiles (show gives the bag's
# derived mesh and inflated state) and runs a falling impact in which the bag, facing away
# from the person, carries no force on it; the same bag declared under the hub meets the head
# before the shell does (contacts lists it first), its history channels record the squeeze,
# and the impact's HIC15 falls below the bare quad's.
. tests/lib.sh

Q='model drop airbags; model drop ra3; model load sessions/quad/quad.urm'
# a bag part for the quad: NAME, the side (top: +1, bottom: -1); the bag's plan 0.12 x 0.10 m
bag_part() { name=$1; s=$2
  rot=""; [ "$s" = 1 ] && rot="rot=1,0,0,180"
  cat <<EOB
part quad_bags
ellipsoid ${name}_shape body=quad_hub pos=0,0,$(awk -v s="$s" 'BEGIN { print 0.1 * s }') size=0.12,0.1,0.06
airbag $name geom=${name}_shape p0=101325 patm=101325 v0=0.003 gamma=1.4 kappa=1.5 \\
       thickness=0.06 mu=0.4 v_eps=0.01 targets=head_cranium,head_face,neck,shoulder_l,shoulder_r \\
       membrane=1 size=0.12,0.10 depth=0.06 mount=0,0,$(awk -v s="$s" 'BEGIN { print 0.055 * s }') $rot mesh=4 \\
       support=quad_shell
sensor ${name}_p type=airbag obj=$name
EOB
}
bag_part quad_top 1 >"$TMP/top.urm"
bag_part quad_bot -1 >"$TMP/bot.urm"
hic() { awk -F, '$1 == "0" && $2 == "0" {print $4; exit}' "$TMP/out"; }

# the bare quad's HIC15 at the centre
run -c "$Q; case Q; set format csv; impact 0 0"
H0=$(hic)
check bare_runs cond '[ $RC -eq 0 ] && [ -n "$H0" ]'

# a top bag: compiles, is a membrane, runs one impact; the person never touches it
run -c "$Q; model load $TMP/top.urm; case Q; show; set format csv; impact 0 0; contacts; history"
check top_compiles cond '[ $RC -eq 0 ] && [ ! -s "$TMP/err" ]'
check top_derived has "$TMP/out" '^# derived, membrane quad_top: 98 nodes, 192 triangles, [0-9]* mount nodes'
check top_impact cond '[ -n "$(hic)" ]'
check top_no_contact cond '! grep -q "^quad_top," "$TMP/out"'
check top_force_zero cond 'grep -q "^quad_top_p_f,0,N," "$TMP/out"'
check top_channels cond 'grep -q "^quad_top_p_p,[0-9.e+]*,Pa," "$TMP/out" && grep -q "^quad_top_p_strain,[0-9.e-]*,1," "$TMP/out"'

# a bottom bag: the first contact with the head, squeezed, and a lower HIC15
run -c "$Q; model load $TMP/bot.urm; case Q; set format csv; impact 0 0; contacts; history"
H1=$(hic)
check bot_runs cond '[ $RC -eq 0 ] && [ -n "$H1" ]'
check bot_first cond '[ "$(grep -m1 ",head_cranium," "$TMP/out" | cut -d, -f1)" = quad_bot ]'
PB=$(awk -F, '$1 == "quad_bot_p_p" {print $2}' "$TMP/out")
FB=$(awk -F, '$1 == "quad_bot_p_f" {print $2}' "$TMP/out")
check bot_squeezed awk -v p="$PB" -v f="$FB" 'BEGIN { exit !(p > 1.2 * 101325 && f > 100) }'
echo "  (HIC15 at the centre: bare quad $H0, with the bottom bag $H1)"
check bot_softer awk -v a="$H0" -v b="$H1" 'BEGIN { exit !(b < 0.9 * a) }'
finish
