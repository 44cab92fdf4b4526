# Worst-case stack depth from GCC's -fcallgraph-info=su output (.ci, VCG).
#   awk -v ROOT_RE='MfbpTracker<float, mptrack::SmallBoardCaps>::step\\(' -f stack_depth.awk *.ci
# Prints "<bytes> <complete> <function label>" for each function whose label
# matches ROOT_RE: the largest sum of static frames along any call path from
# it (its own frame included). complete = 0 when the path meets a call GCC
# could not size (dynamic frame, indirect call, recursion, or a function
# defined in another translation unit without .ci data): the number is then
# a lower bound. Library leaves (memset/memcpy/memmove, sqrt, the __aeabi_*
# run-time helpers: leaf routines of a few words of stack) count 0 bytes.
function depth(n,    i, e, d, best, ok) {
  if (n in memo) return memo[n]
  if (n in onstack) { incomplete[n] = 1; return 0 }  # recursion: unbounded
  onstack[n] = 1
  best = 0
  for (i = 1; i <= nout[n]; ++i) {
    e = out[n, i]
    d = depth(e)
    if (!(e in frame) && !(e ~ /^(memset|memcpy|memmove|sqrtf?|__aeabi_[a-z0-9]+)$/)) unknown[n] = 1
    if ((e in unknown) || (e in incomplete)) incomplete[n] = 1
    if (d > best) best = d
  }
  delete onstack[n]
  if (n in dynamic) incomplete[n] = 1
  if (n in unknown) incomplete[n] = 1
  memo[n] = best + (n in frame ? frame[n] : 0)
  return memo[n]
}
/^node:/ {
  t = $0; sub(/.*title: "/, "", t); sub(/".*/, "", t)
  l = $0; sub(/.*label: "/, "", l); sub(/\\n.*/, "", l)
  label[t] = l
  if (match($0, /[0-9]+ bytes \((static|dynamic[^)]*)\)/)) {
    s = substr($0, RSTART, RLENGTH)
    split(s, parts, " ")
    frame[t] = parts[1] + 0
    if (s ~ /dynamic/) dynamic[t] = 1
  }
}
/^edge:/ {
  s = $0; sub(/.*sourcename: "/, "", s); sub(/".*/, "", s)
  d = $0; sub(/.*targetname: "/, "", d); sub(/".*/, "", d)
  out[s, ++nout[s]] = d
}
END {
  for (t in label) {
    if (label[t] ~ ROOT_RE && (t in frame)) {
      printf "%d %d %s\n", depth(t), (t in incomplete) ? 0 : 1, label[t]
    }
  }
}
