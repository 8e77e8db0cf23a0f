# The settings' words (src/settings/*.rs, src/ui/setting_slider.rs,
# src/ui/tank_panel.rs). Each numeric setting's message is
# setting-<section>-<key> (its key in kebab-case): the label, with .help (hover
# help), .field (a typed field's own help), .fewer and .more (a count's − and +
# buttons); a named value is setting-<section>-<key>-<name> with .help.

## Units shown after a number (with their space).
setting-unit-metres = {" "}m
setting-unit-metres-per-second = {" "}m/s
setting-unit-metres-per-second-squared = {" "}m/s²
setting-unit-degrees = °
setting-unit-times = ×
setting-unit-food = {" "}food
setting-unit-body-lengths = {" "}BL

## A row's controls.
setting-count-fewer = { $label }: fewer
setting-count-more = { $label }: more
setting-named-value = { $name }: { $help }
    .name = { $setting }: { $name }

## Why a setting was refused.
setting-error = setting '{ $key }': { $reason }
setting-error-out-of-range = { $value } is out of range: choose from { $min } to { $max }
setting-error-selected-fish = { $selected } is out of range: there are { $count } fish (0 to { $last }), or null for none
setting-error-selected-animal = { $selected } is out of range: there are { $count } animals (0 to { $last }), or null for none
setting-error-needs-selected-fish = it needs a selected fish: set selected too
setting-error-too-many-obstacles = { $count } obstacles is too many: at most { $max }
setting-error-not-an-object = set() takes an object such as {"{"}"speed": 2{"}"}, not { $value }
setting-error-unknown-key = unknown setting '{ $key }'; the settings are: { $known }
setting-error-wrong-type = { $value } has the wrong type ({ $hint })

## Why a share link could not be opened.
setting-link-too-long = the link is too long ({ $count } characters) to be a Shoal link
setting-link-unknown-version = the link does not start with a Shoal version tag ('{ $tag }')
setting-link-not-base64 = the link is damaged (it is not valid base64 text): perhaps it was cut off when copied
setting-link-not-deflate = the link is damaged (its data cannot be unpacked): perhaps it was cut off when copied
setting-link-not-json = the link's data is not valid settings text
setting-link-invalid = the link asks for something Shoal cannot do: { $reason }
setting-link-sealed-damaged = the link's mystery values are damaged ({ $why }): perhaps the link was cut off or edited when copied
setting-link-sealed-not-base64 = they are not valid base64 text
setting-link-sealed-short = they are too short
setting-link-sealed-checksum = they do not unscramble to what the teacher set
setting-link-sealed-mismatch = they do not match the controls the studio makes a mystery

## The whole app's settings.
setting-app-speed = Speed
    .help = How fast time runs: 1× is real time, 2× is twice as fast
setting-app-seed = Seed
    .help = The number that decides where everything starts. The same seed always gives the same run, so a class can share it
    .field = Type a number to start a new run from it

## One boid tank's settings (schooling lab, aquarium).
setting-tank-containment = Containment
    .help = How strongly a fish stays in the pond: it turns back towards open water before its path comes near the glass, the sand or the surface, and next to them it turns along them instead of into them. At 0 even a school rides along the glass.
setting-tank-alignment = Alignment
    .help = How much a fish copies the direction its neighbours are swimming (close neighbours count more: their heading is easier to see; see Clear sight).
setting-tank-cohesion = Cohesion
    .help = How much a fish swims towards the middle of the neighbours it can see (and of the distant fish it sees; see Distant fish), easing off as it arrives.
setting-tank-separation = Separation
    .help = How much a fish keeps its own space: it moves away from fish inside its personal space, harder the closer they are. Strong separation also slows a school down: inside a school the pushes come from all sides and mostly cancel, but each one still holds the fish back (the Group school swims about 0.29 m/s at separation 25 and 0.18 m/s at 100).
setting-tank-avoidance = Avoidance
    .help = How strongly a fish swerves around obstacles: rocks, pillars, ledges, stingrays, and fish coming straight at it (three or more close together count as one obstacle). The glass, sand and surface are containment's job.
setting-tank-vision-distance-m = Vision distance
    .help = How far a fish can see its neighbours, in metres.
setting-tank-vision-angle-deg = Vision angle
    .help = How wide a fish sees around itself. At 360° it sees behind too; at 300° there is a blind spot behind its tail.
setting-tank-max-speed-m-per-s = Top speed
    .help = The fastest a fish can swim, in metres per second.
setting-tank-max-force-m-per-s2 = Turning power
    .help = How hard a fish can turn or speed up at once (the maximum force). Small values make slow, lazy turns.
setting-tank-personal-space-m = Personal space
    .help = How close another fish may come before separation pushes this one away. A school settles at about one body length (0.3–0.5 m here).
setting-tank-wander = Wander
    .help = How much a fish roams about on its own, 0 to 100 (on the urges' scale). The same for loners and schools: a school's alignment and cohesion overcome it, loners' do not.
setting-tank-clear-sight-m = Clear sight
    .help = Within this distance a fish reads which way a neighbour swims as well as it can; a fish twice as far counts half as much in alignment, because it looks smaller. At 0 a fish reads no heading and alignment has nothing to copy. The same for loners and schools: loners keep farther apart, so they copy each other less.
setting-tank-distant-pull = Distant fish
    .help = How strongly a fish swims towards the fish it sees far away, as a percentage of its pull towards its close neighbours. It is part of cohesion, so it does nothing when cohesion is 0. It lets two schools that see each other join up; at 0 only the close neighbours attract.
setting-tank-min-speed-m-per-s = Slowest speed
    .help = The speed a fish never drops below, in metres per second: fish keep swimming, even when their urges cancel out. A tight school often swims near this speed.
setting-tank-fish-count = Fish
    .help = How many fish (the prey) are in the tank.
    .fewer = Take 10 away
    .more = Add 10
    .few = With 50 fish or fewer the presets differ less: Individual fish meet rarely, but when two meet, their bit of alignment keeps them swimming side by side. Over 20 tanks of 20 fish, the loners' polarization was about 0.4 (up to 0.68 in one tank), where random headings give about 0.2.
    .crowded = With 1,000 fish or more the tank is crowded: Individual fish push each other apart harder than containment holds them in, so they fill the tank up to the glass (at 2,000 fish about a third of them touch it). A Group school lines up less (polarization 0.6 to 0.7 at 1,000 fish, 0.3 to 0.5 at 2,000) and does not settle into one circling ring either.
setting-tank-sharks = Sharks
    .help = Hunters. A shark chases a fish; fish that see it flee and bunch together (while fleeing, a fish's cohesion weight counts double and its separation weight half).
    .fewer = Take 1 away
    .more = Add 1
setting-tank-stingrays = Stingrays
    .help = Flat fish that glide over the sand. Other fish swim around them like rocks.
    .fewer = Take 1 away
    .more = Add 1
setting-aquarium-fish-count = Fish
    .help = How many fish are in the tank

## A tank's presets.
setting-preset-individual = Individual (solitary)
    .help = Fish that like to be alone: they keep their distance and do not try to stay together.
setting-preset-group = Group (school)
    .help = Fish that live in a school: they stay close, swim the same way and still never bump.
setting-preset-monte-carlo-paper = Monte Carlo (paper)
    .help = The lottery mode with the chances published in the paper: each moment one urge wins.
    .note = In the paper's lottery cohesion wins 41 % of the draws and separation only 12.5 %, so the fish pack tighter than in the other presets: nearest neighbours about half a body length apart, and bodies often overlap (at 41 % of the samples a fish had a neighbour closer than half its length; 20 tanks of 200 fish).
setting-preset-custom = Custom
    .help = Your own mix: move any slider and the preset becomes Custom.

## A tank's control modes.
setting-mode-blended = Blended (direct)
setting-mode-classic = Classic
setting-mode-direct-alternate = Direct alternate
setting-mode-monte-carlo = Monte Carlo

## A tank's controls (src/ui/tank_panel.rs).
setting-tank-panel-preset = Preset
    .help = Ready-made mixes of the five urges, from the paper's Table 1
setting-tank-panel-mode = How the urges combine
    .help = The control mode: how a fish turns five urges into one move
    .block = control mode
setting-tank-panel-mode-note = Wander and fleeing from sharks are not urges of the mode: they act on top of it, in every mode.
setting-tank-panel-urges = Urges (0–100)
    .help = How much each urge counts, on the paper's 0 to 100 scale
setting-tank-panel-senses = Senses, body and wander
    .help = Not part of the presets: Individual and Group change only the five urges, so these stay the same when you pick a preset.
setting-tank-panel-animals = Animals

## The physics fish's settings.
setting-physics-fish-count = Fish
    .help = How many muscle-driven fish swim in the tank. Each one is 23 masses joined by 91 springs
setting-physics-sharks = Sharks
    .help = Sharks are built like the fish, only twice as long and four times heavier
    .fewer = One shark fewer
    .more = One more shark
setting-physics-current-m-per-s = Current
    .help = How fast the water flows round the tank. A fish that stops swimming drifts with it; to stay put it must swim against it
setting-physics-hand-speed = Swim
    .help = How hard the tail muscles beat: 0 rests, 1 is the fastest swimming
setting-physics-hand-pitch-deg = Fins
    .help = Tilt the side fins: up makes the fish climb, down makes it dive (only while it swims)
setting-physics-turn-angle-deg = Turn
    .help = The turn the button asks for: positive to the fish's left, negative to its right. Turns above 90° are made of smaller ones

## The reef's settings.
setting-reef-prey-count = Prey fish
    .help = How many small prey fish live in this reef (they school and flee the shark)
setting-reef-food-count = Plankton
    .help = How much plankton drifts in the water; eaten plankton is replaced
setting-reef-visibility-m = Visibility
    .help = How far a fish can see in this water, metres. Murky water: fish see less, find less food and notice the shark later
setting-reef-current-m-per-s = Current
    .help = How fast the water flows; it carries plankton and sways the seaweed
setting-reef-overlay-none = None
setting-reef-overlay-light = Light
setting-reef-overlay-temperature = Temperature

## A reef fish's mind (reef.traits.<kind>.<trait>).
setting-minds-digestion-rate-per-unit = Hunger grows (p0)
    .help = p0: how fast a meal is digested, so how soon the fish is hungry again, per time unit of 1/40 s. Calm (Shoal's default) 0.0003: hungry again 21 s after a full meal. The paper's nominal 0.00067: after 9 s; ravenous 0.005: after 1 s
setting-minds-digestion-rate-per-unit-calm = Calm
    .help = p0 = 0.0003 (Shoal's default)
setting-minds-digestion-rate-per-unit-nominal = Nominal
    .help = p0 = 0.00067 (the paper's)
setting-minds-digestion-rate-per-unit-ravenous = Ravenous
    .help = p0 = 0.005 (the paper's)
setting-minds-libido-rate-per-unit = Libido grows (p1)
    .help = p1: how fast the wish to mate grows after mating, per time unit of 1/40 s. Calm (Shoal's default) 0.0011: a fed fish wants to mate again 6 s after mating. The paper's nominal 0.0025: after 2.5 s; sexual mania 0.01: after 0.6 s
setting-minds-libido-rate-per-unit-calm = Calm
    .help = p1 = 0.0011 (Shoal's default)
setting-minds-libido-rate-per-unit-nominal = Nominal
    .help = p1 = 0.0025 (the paper's)
setting-minds-libido-rate-per-unit-sexual-mania = Sexual mania
    .help = p1 = 0.01 (the paper's)
setting-minds-appetite-food-units = Appetite (α)
    .help = α: how much food fills the fish (a plankton particle is 1, a prey fish 4)
setting-minds-fear-distance-body-lengths = Fear distance (D0)
    .help = D0: a shark nearer than this many body lengths frightens the fish as much as it can be (paper: 3.85)
setting-minds-collision-box-ahead-body-lengths = Collision box
    .help = How far ahead the fish watches for things in its way
setting-minds-collision-box-ahead-body-lengths-timid = Timid
    .help = swerves from anything far ahead (1.5 body lengths)
setting-minds-collision-box-ahead-body-lengths-ordinary = Ordinary
    .help = swerves from what is 0.8 body lengths ahead
setting-minds-collision-box-ahead-body-lengths-courageous = Courageous
    .help = swerves only at the last moment (0.3 body lengths)
setting-minds-persistence-body-lengths = Persistence
    .help = Does the fish stick to the food, prey or partner it chose?
setting-minds-persistence-body-lengths-fickle = Fickle
    .help = switches to any target that is a little nearer
setting-minds-persistence-body-lengths-ordinary = Ordinary
    .help = switches when another is 2 body lengths nearer
setting-minds-persistence-body-lengths-devoted = Devoted
    .help = sticks to its target unless another is 20 body lengths nearer
setting-minds-fear-threshold = Alarm at fear (f0)
    .help = f0: fear above this makes the fish take evasive action (paper: between 0.1 and 0.5)
setting-minds-panic-threshold = Panic at fear (f1)
    .help = f1: when the nearest shark frightens it more than this, a schooling fish stops schooling and flees alone
setting-minds-urge-threshold = Acts on urges at (r)
    .help = r: hunger (or the wish to mate) above this sends the fish looking for food (or a partner) (paper: below 0.5)

## The learning lab's settings.
setting-learning-annealing-steps = Tries per drill
    .help = How many tries the fish gets for each drill. More tries, better swimming (the paper's best shark had 6840). Changing it starts again

## A setting named out of its panel (the Experiment window, the studio's
## rules): src/settings/names.rs.
setting-name-kind = { $kind } · { $label }
setting-name-unit = { $label } ({ $unit })
setting-name-left = { $label } (left tank)
setting-name-right = { $label } (right tank)
setting-name-left-unit = { $label } ({ $unit }, left tank)
setting-name-right-unit = { $label } ({ $unit }, right tank)
setting-name-selected = Selected fish
setting-name-paused = Play and pause
setting-name-scene = Scene
setting-name-physics-behaviour = How the fish swim
setting-name-reef-demo = Reef demo
setting-name-learning-training = Training
setting-name-learning-controller = The swimmer's controls
