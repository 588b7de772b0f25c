# bash completion for drycut (installed to share/bash-completion/completions/drycut).
# Subcommands and their options are read from drycut's own --help, so the completion follows the
# program without being edited; arguments that are not options complete as file names.
_drycut() {
  local cur prev words cword
  _init_completion 2>/dev/null || {
    cur="${COMP_WORDS[COMP_CWORD]}"
    prev="${COMP_WORDS[COMP_CWORD-1]}"
    words=("${COMP_WORDS[@]}")
    cword=$COMP_CWORD
  }
  local drycut="${words[0]}"
  # The subcommand chain typed so far (e.g. "profile import").
  local chain=() w i
  for ((i = 1; i < cword; i++)); do
    w="${words[i]}"
    [[ "$w" == -* ]] && continue
    if "$drycut" "${chain[@]}" --help 2>/dev/null | sed -n '/^[Ss]ubcommands:/,$p' | grep -qE "^  $w( |$)"; then
      chain+=("$w")
    fi
  done
  local help
  help="$("$drycut" "${chain[@]}" --help 2>/dev/null)"
  if [[ "$cur" == -* ]]; then
    local opts
    opts="$(grep -oE -- '(^|[ ,])--?[A-Za-z][A-Za-z0-9-]*' <<<"$help" | tr -d ' ,' | sort -u)"
    mapfile -t COMPREPLY < <(compgen -W "$opts" -- "$cur")
    return
  fi
  local subs
  subs="$(sed -n '/^[Ss]ubcommands:/,$p' <<<"$help" | grep -oE '^  [a-z]+' | tr -d ' ')"
  if [[ -n "$subs" ]]; then
    mapfile -t COMPREPLY < <(compgen -W "$subs" -- "$cur")
    return
  fi
  mapfile -t COMPREPLY < <(compgen -f -- "$cur")
}
complete -o filenames -F _drycut drycut
