# Altered copies of the paper for the shell tests (sourced): each function writes its copy and
# fails (exit status 1) when its substitutions did not change the lines they should.
#   corrected_copy SRC DST   the typos the ledger records as errata corrected: d^6q/dt^5 -> dt^6 (the
#                            Taylor display, twice), the action's sum from j = 0, Gamma's (2,2) entry
#                            over delta, and det Gamma with its factor 1/4: six lines
#   new_error_copy SRC DST   one coefficient of p_r changed (omega^4 -> omega^6): momentum-order-3
#                            turns from holds into an erratum
corrected_copy() {
  sed -e 's/{{\\dd^6 q}\\over{\\dd t^5}}/{{\\dd^6 q}\\over{\\dd t^6}}/g' -e 's/\\sum_{j=1}^{N-1}/\\sum_{j=0}^{N-1}/' \
      -e 's/{{\\gamma^2-1}\\over2}   \\end{pmatrix}/{{\\delta^2-1}\\over2} \\end{pmatrix}/' \
      -e 's/{\\rm det} \\, \\Gamma = /{\\rm det} \\, \\Gamma = {1\\over4} \\, /' "$1" >"$2"
  [ "$(diff "$1" "$2" | grep -c "^>")" = 6 ]
}
new_error_copy() {
  sed 's/{{m \\, \\omega^4}\\over48}/{{m \\, \\omega^6}\\over48}/' "$1" >"$2"
  ! cmp -s "$1" "$2"
}
