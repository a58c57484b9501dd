# bash completion for gfec (and carbot-sim, when sourced from the source tree). Installed by
# cmake --install and the .deb into share/bash-completion/completions/gfec
# (cmake/GfecInstall.cmake); bash-completion loads it on the first <Tab> after "gfec".
# tests/cli/install_files.sh checks what it offers.

_gfec_warnings() {
  # The warning names from gfec itself, so the list never goes stale.
  "${1:-gfec}" --help 2>/dev/null | sed -n 's/^  -W\([a-z-]*\) .*/\1/p'
}

_gfec() {
  local cur prev
  cur=${COMP_WORDS[COMP_CWORD]}
  prev=${COMP_WORDS[COMP_CWORD-1]}
  local gfec=${COMP_WORDS[0]}

  # Options every command takes (the front end's): -I DIR, -x LANG, --period DURATION.
  case $prev in
    -I) COMPREPLY=($(compgen -d -- "$cur")); return ;;
    -x) COMPREPLY=($(compgen -W 'alica gfec iec-st plcopen' -- "$cur")); return ;;
    --period) COMPREPLY=($(compgen -W '10ms 100ms 1s T#10ms T#100ms' -- "$cur")); return ;;
  esac

  # -W<name> and -f<option> complete as the compiler's, below.
  if [[ ${COMP_WORDS[1]} == run && $COMP_CWORD -gt 1 && $cur != -[Wf]?* ]]; then
    case $prev in
      --inputs) COMPREPLY=($(compgen -f -X '!*.csv' -- "$cur")); compopt -o plusdirs 2>/dev/null; return ;;
      --html) COMPREPLY=($(compgen -f -X '!*.html' -- "$cur")); compopt -o plusdirs 2>/dev/null; return ;;
      --ticks|--chart|--agents) return ;;
    esac
    if [[ $cur == -* ]]; then
      COMPREPLY=($(compgen -W '--inputs --ticks --agents --chart --html -I -x --period --observable --hooks
        --check-post -W -w -f --help' -- "$cur"))
    else
      COMPREPLY=($(compgen -f -X '!*.@(sfc|fsm|pml|xml|st|ST)' -- "$cur")); compopt -o plusdirs 2>/dev/null
    fi
    return
  fi

  if [[ ${COMP_WORDS[1]} == monitor && $COMP_CWORD -gt 1 && $cur != -[Wf]?* ]]; then
    case $prev in
      --serial) COMPREPLY=($(compgen -f -- "${cur:-/dev/tty}")); return ;;
      --baud) COMPREPLY=($(compgen -W '9600 19200 38400 57600 115200 230400 460800 921600 1000000' -- "$cur")); return ;;
      --http) COMPREPLY=($(compgen -W '127.0.0.1:8080 127.0.0.1:0' -- "$cur")); return ;;
      --tcp|--silence|--robots|--chart) return ;;
    esac
    if [[ $cur == -* ]]; then
      COMPREPLY=($(compgen -W '--log --http --http-remote --serial --baud --tcp --robots --silence --chart -I -x
        --period -W -w -f --help' -- "$cur"))
    else
      COMPREPLY=($(compgen -f -X '!*.@(sfc|fsm|plan|pml|xml)' -- "$cur")); compopt -o plusdirs 2>/dev/null
    fi
    return
  fi

  if [[ ${COMP_WORDS[1]} == test && $COMP_CWORD -gt 1 && $cur != -[Wf]?* ]]; then
    case $prev in
      --junit) COMPREPLY=($(compgen -f -X '!*.xml' -- "$cur")); compopt -o plusdirs 2>/dev/null; return ;;
      --filter|-j|--jobs) return ;;
    esac
    if [[ $cur == -* ]]; then
      COMPREPLY=($(compgen -W '--junit --filter --engine-only --reference-only -j --jobs -v --verbose -I -x
        --period -W -w -f --help' -- "$cur"))
    else
      COMPREPLY=($(compgen -f -X '!*.test' -- "$cur")); compopt -o plusdirs 2>/dev/null
    fi
    return
  fi

  if [[ ${COMP_WORDS[1]} == fmt && $COMP_CWORD -gt 1 && $cur != -f?* ]]; then
    if [[ $cur == -* ]]; then
      COMPREPLY=($(compgen -W '--check --diff -f --help' -- "$cur"))
    else
      COMPREPLY=($(compgen -f -X '!*.@(sfc|fsm|plan|iface|toolbox|test)' -- "$cur")); compopt -o plusdirs 2>/dev/null
    fi
    return
  fi

  case $prev in
    -o|--output|-MF) COMPREPLY=($(compgen -f -- "$cur")); return ;;
    --chart|-MT|--context-type|--trace-full-every) return ;;
  esac
  case $cur in
    --emit=*) COMPREPLY=($(compgen -P --emit= -W 'c cpp json dot svg toolbox-skeleton chart' -- "${cur#--emit=}")); return ;;
    --engine=*) COMPREPLY=($(compgen -P --engine= -W 'auto readable scalable' -- "${cur#--engine=}")); return ;;
    --trace=*) COMPREPLY=($(compgen -P --trace= -W 'activation calls' -- "${cur#--trace=}")); return ;;
    -fdiagnostics-format=*)
      COMPREPLY=($(compgen -P -fdiagnostics-format= -W 'text json sarif-stderr sarif-file' -- "${cur#*=}")); return ;;
    -fdiagnostics-color=*)
      COMPREPLY=($(compgen -P -fdiagnostics-color= -W 'auto always never' -- "${cur#*=}")); return ;;
    -Werror=*|-Wno-error=*)
      local flag=${cur%%=*}=
      COMPREPLY=($(compgen -P "$flag" -W "$(_gfec_warnings "$gfec")" -- "${cur#*=}")); return ;;
    -Wno-*) COMPREPLY=($(compgen -P -Wno- -W "$(_gfec_warnings "$gfec") error=" -- "${cur#-Wno-}")); compopt -o nospace 2>/dev/null; return ;;
    -W*) COMPREPLY=($(compgen -P -W -W "all error error= no- $(_gfec_warnings "$gfec")" -- "${cur#-W}")); compopt -o nospace 2>/dev/null; return ;;
    -f*)
      COMPREPLY=($(compgen -W '-fdiagnostics-format= -fdiagnostics-color= -fdiagnostics-color -fno-diagnostics-color
        -fdiagnostics-parseable-fixits -fno-diagnostics-show-line-numbers -fmax-errors=' -- "$cur"))
      compopt -o nospace 2>/dev/null; return ;;
    -*)
      COMPREPLY=($(compgen -W '-o -I -x --period --check --analyze --emit= --chart --engine= --no-line-directives
        --context --context-type= --names --trace --trace= --trace-full-every -W -w -Wall -Werror -f -MD -MMD -MF -MP -MT --help --version' -- "$cur"))
      [[ ${COMPREPLY[0]} == *= ]] && compopt -o nospace 2>/dev/null
      return ;;
  esac
  if [[ $COMP_CWORD -eq 1 ]]; then
    COMPREPLY=($(compgen -W 'run test fmt lsp monitor' -- "$cur"))
  fi
  COMPREPLY+=($(compgen -f -X '!*.@(sfc|fsm|plan|iface|toolbox|pml|xml|st|ST)' -- "$cur"))
  compopt -o plusdirs 2>/dev/null
}

_carbot_sim() {
  local cur prev
  cur=${COMP_WORDS[COMP_CWORD]}
  prev=${COMP_WORDS[COMP_CWORD-1]}
  case $prev in
    --world) COMPREPLY=($(compgen -f -X '!*.json' -- "$cur")); compopt -o plusdirs 2>/dev/null; return ;;
    --trace|--json|--svg|--gfec|--cc|--cxx) COMPREPLY=($(compgen -f -- "$cur")); return ;;
    --cache|--work-dir) COMPREPLY=($(compgen -d -- "$cur")); return ;;
    --seconds|--physics-step|--period) return ;;
  esac
  if [[ $cur == -* ]]; then
    COMPREPLY=($(compgen -W '--world --seconds --trace --json --svg --physics-step --period --gfec --cc --cxx
      --cache --work-dir -q --quiet --help' -- "$cur"))
  else
    COMPREPLY=($(compgen -f -X '!*.@(sfc|fsm|plan)' -- "$cur")); compopt -o plusdirs 2>/dev/null
  fi
}

complete -F _gfec gfec
complete -F _carbot_sim carbot-sim
