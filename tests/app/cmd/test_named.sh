# test_named.sh: the parameters 'set' also takes by name (src/app/cmd/named.c): bag_model
# analytic|membrane is the model parameter bag_membrane 0|1, endrun window|final is endrun 0|1
# (and endrun takes its number too); a wrong word, a unit, or a model without the parameter is
# one error line naming what is accepted. show takes the names set takes (Tab offers them after
# show too): show bag_model prints the word and the parameter, or says the model lacks it.
. tests/lib.sh
run -c 'set bag_model analytic; show bag_membrane; set bag_model membrane; show bag_membrane'
check "bag_model sets bag_membrane" cond '[ "$RC" -eq 0 ] &&
  [ "$(awk "{ print \$2 }" "$TMP/out" | tr "\n" " ")" = "0 1 " ]'
run -c 'set endrun window; show endrun; set endrun final; show endrun; set endrun 0; show endrun'
check "endrun by name and by number" cond '[ "$RC" -eq 0 ] &&
  [ "$(awk "{ print \$2 }" "$TMP/out" | tr "\n" " ")" = "0 1 0 " ]'
run -c 'set bag_model foam; show bag_membrane'
check "a wrong word: one line, what is accepted" cond '[ "$RC" -ne 0 ] &&
  [ "$(wc -l <"$TMP/err")" -eq 1 ] &&
  grep -q "set bag_model: expected analytic or membrane (got .foam.)" "$TMP/err"'
run -c 'set endrun final s'
check "a unit refused" grep -q "set endrun: expected window or final (got 'final' and a unit)" "$TMP/err"
# show NAME for a name set takes: the word the value stands for, and the parameter behind it
run -c 'show bag_model; set bag_model analytic; show bag_model'
check "show bag_model: the word and the parameter" cond '[ "$RC" -eq 0 ] &&
  [ "$(awk "{ print \$2 }" "$TMP/out" | tr "\n" " ")" = "membrane analytic " ] &&
  grep -q "(bag_membrane 0; set bag_model analytic|membrane)" "$TMP/out"'
run -c 'set format json; show bag_model'
check "show bag_model in json" grep -q '"name":"bag_model","value":"membrane"' "$TMP/out"
# a model without the parameter: one line, from set and from show
for cmd in "set bag_model membrane" "show bag_model"; do
  run -c "model drop airbags; $cmd"
  check "$cmd without the parameter: one line" cond '[ "$RC" -ne 0 ] &&
    [ "$(wc -l <"$TMP/err")" -eq 1 ] &&
    grep -q "${cmd%% *} bag_model: the model has no parameter bag_membrane" "$TMP/err"'
done
finish
