# The teacher's studio: its window, the H / L / ? toggles, the student link,
# the question card, what a student sees of a rule, and the rules' errors.

studio-button = Teacher's studio
    .help = Hide, lock or make a mystery of any control, write your own question, and share the result with your class as a link and a QR code
studio-mystery-value = ? (mystery value)
    .help = Your teacher hid this number. Watch what the fish do and work out what it must be.
studio-locked = Locked by your teacher for this lesson
studio-toggle-hide = H
    .help = Hide: students do not see this control
studio-toggle-lock = L
    .help = Lock: students see it greyed and cannot change it
studio-toggle-mystery = ?
    .help = Mystery: students see the fish but not this number (it is locked too)
studio-toggle-hide-name = Hide { $key }
studio-toggle-lock-name = Lock { $key }
studio-toggle-mystery-name = Make { $key } a mystery
studio-toggle-help = { $help } ({ $key })
studio-teacher-asks = Your teacher asks
studio-share = Share with class
    .help = A link and a QR code that open this setting in the student view
studio-share-intro = Project this QR code or send the link: it opens Shoal as it is now, in the student view (your rules in force, your question shown).
studio-copy-link = Copy link
    .help = Put the students' link on the clipboard
studio-link-copied = Students' link copied. It opens the student view: your rules in force and your question shown.
studio-open-student-view = Open the student view in a new tab
    .help = Check what your students will see
studio-intro = Beside every control in the side panel: H hides it from your students, L locks it (they see it greyed), ? makes its value a mystery (they see the fish, not the number, and must work it out; it is locked too).
studio-intro-note = The students' page starts from the settings you have now: choose the scene, the sliders and the seed first.
studio-question = Your question for the class
studio-question-hint = e.g. How strongly do these fish copy their neighbours?
studio-rules = Rules
studio-no-rules = None yet: every control is free.
studio-rule = { $key }: { $what }
studio-rule-hidden = hidden
studio-rule-locked = locked
studio-rule-mystery = mystery
studio-remove = Remove

# Why a studio (in a link or shoal.set) is refused.
studio-error-student-view = this is the student view of a teacher's link: its studio cannot be changed here (open Shoal without the link to edit)
studio-error-kept = { $how ->
    [mystery] a mystery value
    [hidden] hidden
   *[locked] locked
} by the teacher's studio: students cannot change it (changing it would change it through another control)
studio-error-question-long = the question is { $count } characters long: at most { $max }
studio-error-too-many-rules = { $count } rules: at most { $max }
studio-error-not-an-object = expected an object such as {"{"}"question": "…", "rules": {"{"}"left.alignment": {"{"}"mystery": true{"}"}{"}"}{"}"}, got { $value }
studio-error-expected-bool = expected true or false, got { $value }
studio-error-expected-text = expected text, got { $value }
studio-error-rules-not-an-object = expected an object of rules by control, such as {"{"}"left.alignment": {"{"}"locked": true{"}"}{"}"}, got { $value }
studio-error-unknown-field = unknown: the studio's settings are student_view, question and rules
studio-error-rule-not-an-object = expected a rule such as {"{"}"hidden": true{"}"} (or null to remove it), got { $value }
studio-error-unknown-flag = unknown flag '{ $flag }': a rule has hidden, locked and mystery
studio-error-flag-not-bool = '{ $flag }' must be true or false, got { $value }
studio-error-no-control = no control is named '{ $key }': rules name a control by its setting, as in settings(), e.g. left.alignment, speed or physics.current_m_per_s
