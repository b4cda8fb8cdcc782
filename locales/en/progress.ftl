# The learner's progress (src/view/learner_progress, src/ui/kit/progress_panel): the progress
# file's problems, its panel (name, export, import), the home page's progress and the class page
# (#/class, src/view/class_summary). Loaded with an exercises section, the home page's progress
# and #/class, in no page's first load.

## The learner's progress file (bsv_progress.json)
progress-error-not-text = This file could not be read as progress: { $detail }
progress-error-too-big = This file is { $size } ({ $bytes } bytes); a progress file may be at most { $limit }. It was not read.
progress-error-empty-file = This file is empty.
progress-error-too-deep = This file nests lists or objects more than { $max } deep (line { $line }, column { $column }); a progress file nests 3 deep.
progress-error-not-json = This file is not JSON: the text stops making sense at line { $line }, column { $column }.
progress-error-not-an-object = This JSON file holds { $kind ->
    [array] a list
    [text] a piece of text
    [number] a number
    [boolean] true or false
    *[other] null
}, not a progress record.
progress-error-no-format = This JSON file is not a BSV progress file: it has no “format” field (a progress file says "format": "bsv-progress").
progress-error-format = This file is not a BSV progress file (format “{ $found }”, expected “bsv-progress”).
progress-error-version = This progress file was written by another version (version { $found }; this app reads version { $version }).
progress-error-unknown-field = The progress file has a field this app does not know: “{ $field }”.
progress-error-exercise-unknown-field = Exercise { $exercise } has a field this app does not know: “{ $field }”.
progress-error-missing-field = The progress file has no “{ $field }” field.
progress-error-exercise-missing-field = Exercise { $exercise } has no “{ $field }” field.
progress-error-wrong-type = The progress file's field “{ $field }” must be { $expected ->
    [text] text
    [number] a whole number
    [boolean] true or false
    *[list] a list of exercises
}.
progress-error-exercise-wrong-type = Exercise { $exercise }, field “{ $field }”: must be { $expected ->
    [text] text
    [number] a whole number
    [boolean] true or false
    *[list] a list
}.
progress-error-exercise-not-an-object = Exercise { $exercise } is not an object with an id and its attempts.
progress-error-too-many-exercises = A progress file holds at most { $max } exercises; this one has { $count }.
progress-error-bad-id = Exercise { $exercise }: “{ $id }” is not an exercise id.
progress-error-duplicate-id = The exercise “{ $id }” appears twice.
progress-error-attempts = Exercise { $exercise }: more attempts than this app counts.
progress-error-inconsistent = The exercise “{ $id }” does not add up: done needs an attempt, and right at the first try needs done.
progress-error-name-too-long = A learner's name may be at most { $max } characters.
progress-error-build-too-long = The field “build” is longer than { $max } characters.

## The class summary (#/class)
class-duplicate = A second file of { $learner } (the first is { $first }) { $same ->
    [same] with the same progress: left out.
    *[different] with different progress: left out; the first file's progress is shown.
}

## The progress panel (each exercises section, the home page)
progress-name-label = Your name (optional; it goes in the exported file)
progress-export = Export progress
progress-import = Import progress
progress-imported = { $file }: { $count ->
    [one] one exercise
   *[other] { $count } exercises
} merged into your progress.
progress-imported-unknown = { $file }: { $count ->
    [one] one exercise
   *[other] { $count } exercises
} merged into your progress; { $unknown } more from a newer version of the app kept for it.
progress-file-problem = { $file }: { $problem }
progress-not-saved = This browser does not keep your progress (its storage is off): export it before you leave.
progress-not-saved-full = This browser's storage is full, so your progress is not kept: export it before you leave.

## The home page's progress
home-progress-heading = Your exercises
home-progress-intro = Each drill page ends with exercises: predict, then check against the page's own numbers. Your progress stays in this browser; export it for your teacher, or import it on another device.
home-progress-page = { $done } / { $total }
home-progress-page-label = { $page }: { $done } of { $total } exercises done
home-progress-class = Teachers: open your class's progress files on the class page →

## The class page (#/class)
class-title = Class progress
class-lede = Open your learners' bsv_progress.json files, as many as you like at once, or drop them here: a table of who has done what, and each exercise's success rate. Nothing leaves this browser.
class-files-label = Progress files
class-pick = Open progress files
class-clear = Clear
class-drop = Drop progress files here
class-empty = No progress file opened yet.
class-counts = { $learners ->
    [one] One learner
   *[other] { $learners } learners
}, { $files ->
    [one] one file left out
    [0] no file left out
   *[other] { $files } files left out
}.
class-rejected-heading = Files left out
class-table-heading = Learners by exercise
class-table-caption = ✓ right at the first try, ◐ right later, · not yet.
class-learner = Learner
class-file = File
class-standing-first-try = right at the first try
class-standing-later = right later
class-standing-not-yet = not yet
class-unknown-ids = { $count ->
    [one] one more exercise
   *[other] { $count } more exercises
} of a newer version
class-rates-heading = Exercises, hardest first
class-rate-exercise = Exercise
class-rate-page = Page
class-rate-success = Done
class-rate-first-try = Right at the first try
class-rate-value = { $rate } %
class-download = Download the summary (CSV)
