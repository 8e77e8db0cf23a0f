# The Experiment… window (sweeps of a setting over levels and seeds), its
# plots and table, and the errors of a design or an experiment link.

experiment-open = Experiment…
    .help = Run the tank many times: vary a setting over levels and seeds, measure the school, and plot the answer
experiment-window = Experiment
experiment-intro = Run this tank many times: vary a setting, repeat each level with other seeds, and measure the school. The tank on screen keeps swimming.
experiment-running-design = { $name }: { $runs } runs of { $secs } s
experiment-cannot-start = Cannot start: { $field }: { $reason }
experiment-start = Start
    .help = Run every level with every seed, a little each frame
experiment-save-design = Save design
    .help = Download this design as a file: shoal-lab runs it on many cores
experiment-save-design-next = run it with shoal-lab run, or keep it for next time
experiment-measuring-pace = measuring the pace…
experiment-progress = { $done } of { $total } runs · { $left }
experiment-progress-paused = { $done } of { $total } runs · paused
experiment-pause = Pause
    .help = Stop the runs for now
experiment-resume = Resume
experiment-cancel = Cancel
    .help = Stop for good; the runs already finished are kept
experiment-cancelled = Cancelled: the { $done } completed runs of { $total } are kept below.
experiment-done = Done: { $count } runs.
experiment-watching = Watching the run with { $levels }, seed { $seed }, from its start.
experiment-download-csv = Download CSV
    .help = Every run's numbers, one row per run and measure
experiment-download-csv-next = open it with a spreadsheet
experiment-new = New experiment
    .help = Put these results away and design another (download them first)
experiment-copy-link = Copy link
    .help = Copy a link that opens Shoal on this experiment and runs it again: the same runs, the same numbers
experiment-name = Name
experiment-vary = Vary
    .help = The setting that changes from run to run
experiment-then = Then
experiment-second = and a second setting
    .help = One curve per level of a second setting
experiment-seeds = Seeds
    .help = Each level is run once per seed: the same fish, a different start
experiment-from-seed = from seed
experiment-warmup = Warm-up
    .help = Seconds of each run before measuring: the school forms
experiment-measure-for = Measure for
    .help = Seconds of each run measured after the warm-up
experiment-measures = Measures
experiment-mean = mean
    .help = The mean over the measuring time
experiment-final = final
    .help = The value at the end of the run
experiment-off-and-on = off and on
experiment-range-from = from
experiment-range-to = to
experiment-range-in = in
experiment-range-levels = levels
experiment-runs = Runs
experiment-runs-value = { $levels } levels × { $seeds } seeds = { $runs }
experiment-steps-per-run = Steps per run
experiment-steps-value = { $warmup } warm-up + { $measured } measured ({ $dt } s each)
experiment-time = Time
experiment-time-help = { $compute } of computing, done { $ms } ms a frame while the tank keeps swimming (more on a computer that draws under 30 frames a second)
experiment-duration-under-second = under a second
experiment-duration-secs = about { $value } s
experiment-duration-min = about { $value } min
experiment-duration-hours = about { $value } h

# The measures that are not the plots' own (those keep the metrics plots'
# names): src/experiment/measure.rs.
experiment-measure-distance-swum = Distance swum (m)
    .help = How far the average fish swam while it was measured, in metres
experiment-measure-catches = Prey caught
    .help = How many fish the sharks (or the predators) caught while it was measured
experiment-measure-food-eaten = Plankton eaten
    .help = How many bits of plankton the fish ate while it was measured
experiment-measure-spawnings = Spawnings
    .help = How many times a pair spawned (laid and fertilised eggs) while it was measured
experiment-measure-missed-strikes = Missed attacks
    .help = How many times a predator attacked and missed, confused by the crowd of prey
experiment-measure-fish-collisions = Fish collisions
    .help = How many times two fish bumped into each other while it was measured
experiment-measure-prey-alive = Prey alive
    .help = How many prey fish are still alive

# The results: plots and table.
experiment-level-on = on
experiment-level-off = off
experiment-no-run-yet = No run has finished yet.
experiment-plot-title = { $measure } · { $summary }
experiment-no-factor = (no factor)
experiment-interval-about = Bars and [brackets]: a 95 % interval. Run many more seeds and their average would very likely fall inside it. It is worked out by drawing again from the seeds you ran (a bootstrap), so it never goes past what the measure can be.
experiment-few-seeds = { $count ->
    [one] Only { $count } seed per level: these intervals are rough. Use 5 or more seeds for a surer answer.
   *[other] Only { $count } seeds per level: these intervals are rough. Use 5 or more seeds for a surer answer.
}
experiment-table-title = Mean over seeds [95 % interval]
experiment-table-watch = watch a run
experiment-interval = { $mean } [{ $low }, { $high }]
experiment-seed-button = seed { $seed }
    .help = Set the tank to this level and seed, from the start: watch this very run

# Why a design is refused: the field, then the reason.
experiment-error = { $field }: { $reason }
experiment-error-json-place = (file, line { $line }, column { $column })
experiment-error-too-many-factors = { $count } factors: at most { $max }
experiment-error-factor-twice = '{ $key }' is already a factor
experiment-error-no-sample = { $secs } s holds no metrics sample: measure for at least { $min } s
experiment-error-too-many-runs = { $runs } runs (levels × seeds): at most { $max }
experiment-error-link-empty = the link is empty
experiment-error-seeds-and-count = give either seeds (a list) or count (and first_seed), not both
experiment-error-first-seed-with-list = goes with count, not with a list of seeds
experiment-error-how-many-seeds = say how many seeds (count) or which (seeds)
experiment-error-no-replicates = no replicates: at least one seed
experiment-error-too-many-seeds = { $count } seeds: at most { $max }
experiment-error-seed-range = seed { $seed } is out of range: choose from 0 to { $max }
experiment-error-seed-twice = seed { $seed } appears twice: a replicate would repeat a run
experiment-error-no-measures = nothing to measure: name at least one measure
experiment-error-unknown-measure = unknown measure '{ $name }'; the measures are: { $known }
experiment-error-measure-not-here = '{ $name }' is not measured in the { $scene } ({ $id }); there: { $known }
experiment-error-nothing = nothing
experiment-error-unknown-summary = unknown summary '{ $name }': choose mean, final or series
experiment-error-measured-twice = { $name } ({ $summary }) is already measured
experiment-error-unknown-setting-there = unknown setting; the settings there are: { $known }
experiment-error-seed-factor = seeds are the replicates: set them in replicates
experiment-error-display-only = '{ $key }' changes how a run is shown, not what happens in it
experiment-error-selection = '{ $key }' chooses the fish shown in detail, not what happens in a run
experiment-error-does-not-act = '{ $key }' does not act in the { $scene } ({ $id }); its settings there are under '{ $section }.'
experiment-error-unknown-setting = unknown setting
experiment-error-not-a-slider = '{ $key }' is not a number or an on/off setting: a factor varies one slider or switch
experiment-error-no-levels = no levels: at least one
experiment-error-too-many-levels = { $count } levels: at most { $max }
experiment-error-level-not-switch = { $level } is not a level of '{ $key }': it takes true or false
experiment-error-level-not-number = { $level } is not a level of '{ $key }': it takes numbers
experiment-error-level-twice = level { $level } appears twice
experiment-error-range-field = unknown field: a range has from, to and steps
experiment-error-not-a-number = missing, or not a number
experiment-error-not-whole = missing, or not a whole number
experiment-error-one-step = one step cannot go from one value to another: at least 2
experiment-error-levels-shape = give a list ([0, 50, 100]) or a range ({"{"}"from": 0, "to": 100, "steps": 3{"}"})
experiment-error-secs-range = { $secs } is out of range: choose from 0 to { $max } s
experiment-error-zero-secs = 0 s measures nothing

# Why an experiment link could not be opened.
experiment-link-empty = the link holds no experiment
experiment-link-refused = its experiment cannot run: { $reason }
