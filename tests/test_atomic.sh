# test_atomic.sh: every writer (save session, export grid, export history, export contacts,
# model save) writes a temporary file beside the target and renames it: a write that fails (the
# file size limit, ulimit -f, stands for a full disk) or a rename that fails (the target is a
# directory) leaves the old file intact and no temporary file behind; a good write keeps the old
# file's mode
. tests/lib.sh

U=$(cd "$(dirname "$UASRISK")" && pwd)/$(basename "$UASRISK")
printf 'along,0.00,0.05,0.10\n0.10,0,2,0\n0.05,50,100,10\n0.00,100,95,0\n-0.05,0,4,0\n' \
  >"$TMP/small.csv"
# a grid of 400 cells, so that its export is larger than the size limit
awk 'BEGIN { print "dpar,dperp,p"; for (i = 0; i < 20; i++) for (j = -10; j < 10; j++)
       printf "%.2f,%.2f,%.3f\n", i * 0.05, j * 0.05, (i + j + 30) % 10 / 10 }' >"$TMP/g400.csv"

# the commands that make each writer's content, and the writer
pre_session='case B; set wind 4'
pre_grid="grid load $TMP/g400.csv"
pre_history='case C; impact 0 0'
pre_contacts='case C; impact 0.25 0.25'
pre_model='case A'
write_session='save session'
write_grid='export grid'
write_history='export history'
write_contacts='export contacts'
write_model='model save'
# the size limit of the failing write, in 512-byte blocks, below the size of what is written: one
# impact's contacts are a few hundred bytes (6 pairs, 406 bytes here), so theirs fail at once
lim_session=1 lim_grid=1 lim_history=1 lim_contacts=0 lim_model=1

# no temporary file beside the target
no_temp() { ! ls "$TMP/d" | grep -q '\.tmp\.'; }

for w in session grid history contacts model; do
  eval "pre=\$pre_$w; cmd=\$write_$w; lim=\$lim_$w"
  mkdir -p "$TMP/d"
  printf 'OLD CONTENT\n' >"$TMP/d/$w.out"

  # writes fail past lim x 512 bytes; SIGXFSZ is not trapped here: uasrisk must survive it
  # itself. The message goes to its file through a pipe, and the status through fd 3, which the
  # limit does not reach
  RC=$( { { (ulimit -f "$lim"; exec "$U" -c "$pre; $cmd $TMP/d/$w.out") 2>&1 >/dev/null
            echo $? >&3; } | cat >"$TMP/err"; } 3>&1 )
  check "${w}_write_fails" cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
    has "$TMP/err" ": cannot write .*/d/$w.out.: File too large; the file is unchanged$"'
  check "${w}_old_intact" [ "$(cat "$TMP/d/$w.out")" = "OLD CONTENT" ]
  check "${w}_no_temp_after_write" no_temp

  # the rename fails: a directory stands where the file goes
  mkdir -p "$TMP/d/$w.dir"
  run -c "$pre; $cmd $TMP/d/$w.dir"
  check "${w}_rename_fails" cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
    has "$TMP/err" "cannot write .*/d/$w.dir.: Is a directory; the file is unchanged$" &&
    [ -d "$TMP/d/$w.dir" ]'
  check "${w}_no_temp_after_rename" no_temp

  # a good write replaces the file whole and keeps its mode
  chmod 640 "$TMP/d/$w.out"
  run -c "$pre; $cmd $TMP/d/$w.out"
  check "${w}_written" cond '[ "$RC" -eq 0 ] && [ "$(wc -c <"$TMP/d/$w.out")" -gt $((lim * 512)) ] &&
    ! grep -q "OLD CONTENT" "$TMP/d/$w.out"'
  check "${w}_mode_kept" [ "$(stat -c %a "$TMP/d/$w.out")" = 640 ]
  check "${w}_no_temp_after_success" no_temp
  rm -rf "$TMP/d"
done

# a new file: the mode a plain fopen gives (0666 less the umask)
(umask 027; exec "$U" -c "grid load $TMP/small.csv; export grid $TMP/new.csv") >/dev/null 2>&1
check new_file_mode [ "$(stat -c %a "$TMP/new.csv")" = 640 ]

# what the writer refuses before writing leaves no file at all
run -c "export grid $TMP/none.csv"
check no_grid_no_file cond '[ "$RC" -eq 1 ] && [ ! -e "$TMP/none.csv" ] &&
  ! ls "$TMP" | grep -q "none.csv.tmp"'
run -c "save session /nonexistent/dir/s.ses"
check missing_dir cond '[ "$RC" -eq 1 ] && [ "$(lines "$TMP/err")" -eq 1 ] &&
  has "$TMP/err" "save session: cannot write ./nonexistent/dir/s.ses.: No such file or directory$"'

finish
