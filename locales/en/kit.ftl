# Messages of the page kit's widgets (src/ui/kit). Ids start with `kit-`.

## URL state notice (kit::url_state)
kit-url-unknown = This link has settings this page does not take, which were ignored: { $keys }.
kit-url-invalid = These settings in the link could not be used and kept their defaults: { $keys }.
kit-url-flagged = Some values in this link are not valid ({ $keys }); the message beside each field says why.
kit-url-file = This link used the file “{ $name }”; open it again to run.

## Stepper (kit::stepper)
kit-stepper-label = Step through
kit-stepper-start = Jump to the start (Home)
kit-stepper-back = One step back (← or Page Up)
kit-stepper-run = Play (Space)
kit-stepper-pause = Pause (Space)
kit-stepper-step = One step forward (→ or Page Down)
kit-stepper-end = Jump to the end (End)
kit-stepper-reset = Start over (R)
kit-stepper-speed = Speed
kit-stepper-speed-rate = { $rate } steps / s
kit-stepper-speed-max = As fast as possible
kit-stepper-scrub = Position
kit-stepper-position = Step { $index } of { $len }
kit-stepper-position-open = Step { $index }
kit-stepper-key-step = One step forward
kit-stepper-key-back = One step back (exact)
kit-stepper-key-run = Play or pause
kit-stepper-key-ends = Jump to the start / the end
kit-stepper-key-reset = Start over

## Parameter form (kit::form)
kit-form-args = Arguments, in command-line order
kit-form-options = Options
kit-form-options-note = Extras of the bsv command line. The Python recipe has no options: it always uses these defaults.
kit-form-default = Default:
kit-form-involved = This value is part of the same limit as { $field }.
kit-form-file-open = Open a CSV file…
kit-form-file-sample = Use the built-in labeled sample

## Exports: downloads and command lines (kit::exports)
kit-exports-download = Download { $file }
kit-exports-download-failed = { $file } could not be saved: { $error }
kit-exports-title = The same run on the command line
kit-exports-hint = Run either line in a terminal to get the same files (the Python recipe needs Python 3 and its libraries; bsv is this project's command line).
kit-exports-python = Python recipe
kit-exports-bsv = BSV command line
kit-exports-copy = Copy
kit-exports-copied = The command is copied to the clipboard.
kit-exports-copy-failed = This browser blocked copying: select the command and press Ctrl+C (⌘C on a Mac).
kit-exports-python-no-options = The Python recipe has no options, so its line leaves out { $options } and gives the default result; only the bsv line reproduces this run.
kit-exports-file-note = Run these lines in the folder that holds { $name }.

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

## 3D view (kit::orbit)
kit-orbit-presets = Preset views
kit-orbit-view-iso = Iso
kit-orbit-view-top = Top
kit-orbit-view-front = Front
kit-orbit-view-side = Side
kit-orbit-hint-mouse = Mouse: drag to orbit, wheel to zoom.
kit-orbit-hint-touch = Touch: drag sideways to orbit, pinch to zoom.
kit-orbit-hint-keys = Keys, the view focused: arrows orbit, + / − zoom.
kit-orbit-key-orbit = Orbit the 3D view (when it has focus; Shift for bigger steps)
kit-orbit-key-zoom = Zoom the 3D view in / out (when it has focus)

# Section headings of the pages built on the kit's layout (the signal pages, Umeyama).
signals-params-title = Parameters
signals-explain-title = What you are looking at
signals-quirks-title = Where this port decides for the recipe
signals-exports-title = Downloads and command lines
