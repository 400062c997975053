# What a failing run of a fuzz target says about itself, read from its log (sourced by
# ci/fuzz-nightly and ci/bisect-step, so that the nightly's deduplication and the bisection's
# "same failure" agree).

# The property a crash log names, e.g. "I5" or "heap-buffer-overflow".
property_of() {
  local log=$1 line
  line=$(grep -m1 -o 'tetcut-fuzz: [^ ]* violated after operation [0-9]* ([^)]*)' "$log")
  if [[ -n $line ]]; then
    sed -E 's/^tetcut-fuzz: ([^ ]*) .*/\1/' <<<"$line"
    return
  fi
  line=$(grep -m1 -oE 'ERROR: (AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer): [a-zA-Z-]+' "$log")
  [[ -n $line ]] && { sed -E 's/.*: //' <<<"$line"; return; }
  grep -q 'runtime error:' "$log" && { echo "ubsan"; return; }
  grep -q 'ERROR: libFuzzer: timeout' "$log" && { echo "timeout"; return; }
  grep -q 'out-of-memory' "$log" && { echo "oom"; return; }
  grep -q 'deadly signal' "$log" && { echo "signal"; return; }
  echo "unknown"
}

# "operation 7 (remove)", or nothing.
operation_of() {
  grep -m1 -o 'violated after operation [0-9]* ([^)]*)' "$1" | sed -E 's/violated after //' || true
}

# The line that says what broke: the harness's abort line, else the sanitizer's, else nothing.
headline_of() {
  grep -m1 -E '^tetcut-fuzz: |ERROR: [A-Za-z]+Sanitizer|runtime error:|ERROR: libFuzzer' "$1" | cut -c1-300 || true
}

# The top three stack frames of our own code (not libFuzzer, the sanitizers, libc or the
# harness's own fail()), function names only: stable across builds, unlike addresses.
frames_of() {
  grep -E '^ +#[0-9]+ 0x[0-9a-f]+ in ' "$1" |
    sed -E 's/^ +#[0-9]+ 0x[0-9a-f]+ in ([^ ]+( [^/ ]+)*) .*/\1/; s/\(.*//' |
    grep -vE '^(__|abort|raise|fuzzer::|tetcut::fuzz::fail|std::abort|LLVMFuzzer|main$|_start|gsignal)' |
    head -3 | paste -sd ';' -
}

# Targets whose inputs `tetcut replay` decodes into a scenario.
replayable() { [[ $1 == removal_sequence || $1 == cut_sequence ]]; }
