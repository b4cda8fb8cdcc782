# Messages of the page kit's widgets (src/ui/kit). Ids start with `kit-`.

## Progress panel of a long run (kit::progress)
kit-progress-label = Progress of the run
kit-progress-starting = Starting…
kit-progress-rows = { $done } of { $total } rows ({ $percent } %)
kit-progress-time = { $elapsed } so far
kit-progress-time-left = { $elapsed } so far, about { $left } left
kit-progress-seconds = { $s } s
kit-progress-minutes = { $min } min { $s } s
kit-progress-cancel = Cancel

## Long runs in the background (kit::worker)
kit-worker-failed = The background run stopped unexpectedly ({ $detail }). Try again; if it keeps failing, reload the page.
