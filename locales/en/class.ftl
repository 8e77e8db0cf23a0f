# A class together (issue 37): starting and joining a class, the teacher's
# dashboard and what a student reads about their class.
class-start = Start a class
    .help = Give your class a code to join: they see your investigation or studio setup, and you see their predictions, runs and answers
class-join = Join a class
    .help = Join your teacher's class with its code and a nickname
class-start-intro = Choose what the class will do. Each student's tank runs its own seed (the class seed plus their join order).
class-lesson-studio = The current studio setup (its locks and mysteries)
class-start-go = Start the class
class-starting = Starting…
class-start-failed = The class could not be started: { $reason }
class-join-intro = Type the code your teacher shows and a nickname. Use a first name or a made-up name: it is the only thing about you the class server keeps.
class-code = Class code
class-nickname = Nickname
    .help = At most 24 characters
class-join-go = Join
class-bad-code = A class code is 6 letters and digits, as your teacher shows it.
class-bad-nickname = Type a nickname of 1 to 24 characters.
class-dashboard = Class dashboard
class-code-to-join = Class code (or scan the QR code):
class-copy-teacher-link = Copy my teacher link
    .help = The secret link that opens this dashboard on another computer. Do not show it to students.
class-teacher-link-copied = Teacher link copied. Keep it secret: whoever has it sees the whole class.
class-waiting-for-view = Waiting for the class server…
class-pacing = Pacing
class-hold-at = Hold the class at
class-no-hold = no hold
class-release = Release the next step
    .help = Let the class go one step further
class-pause-all = Pause every tank
    .help = Every student's tank stops: "look up here"
class-reveal = Reveal the predictions
    .help = The students see how many chose each answer (never who)
class-send-setting = Send my setting to everyone
    .help = Every student's tank takes the settings of your tank (their own seed stays; the studio's locks hold)
class-setting-too-large = This setting is too large to send.
class-roster = Students: { $count }
class-step-counts = Look { $look } · Predict { $predict } · Run { $run } · Explain { $explain }
class-col-student = Student
class-col-step = Step
class-col-prediction = Prediction
class-col-runs = Runs
class-student-n = Student { $n }
class-predictions = Predictions
class-predictions-hidden = Hidden from the students until you reveal them.
class-predictions-revealed = The students see these counts.
class-predictions-none = No predictions yet.
class-pooled = The pooled result (every run, each on its own seed)
class-pooled-none = No runs yet.
class-pooled-line = Mean { $mean } (95 % interval { $low } to { $high }), n = { $n } { $n ->
        [one] run
       *[other] runs
    } from { $students } { $students ->
        [one] student
       *[other] students
    }
class-pooled-line-one = Mean { $mean }, n = { $n } { $n ->
        [one] run
       *[other] runs
    } from { $students } { $students ->
        [one] student
       *[other] students
    } (an interval needs two runs)
class-answers = Explain answers
class-answers-none = No answers yet.
class-anonymise = Anonymise
    .help = Show "Student 1, 2, …" instead of nicknames (for the projector); the download keeps the nicknames
class-download = Download class data
    .help = The class's CSV: each student's seed, prediction and measured values
class-download-failed = The class data could not be downloaded: { $reason }
class-delete = Delete class
    .help = Delete the class and everything in it from the server now
class-delete-confirm = Delete this class and all its students' work from the server? This cannot be undone.
class-delete-yes = Delete it
class-delete-no = Keep it
class-delete-failed = The class could not be deleted: { $reason }
class-deleted = The class was deleted from the server.
class-leave = Leave the class
    .help = Forget this class in this browser (the class goes on on the server)
class-step-look = look
class-step-predict = predict
class-step-run = run
class-step-explain = explain
class-connected = connected
class-connecting = connecting…
class-reconnecting = reconnecting in { $secs } s
class-link-ended = not connected
class-status = Class { $code }: { $link }
class-status-waiting = Class { $code }: { $link }, { $count } { $count ->
        [one] message
       *[other] messages
    } waiting
class-you-are = You are { $nickname } (student { $order }, seed { $seed })
class-held = Your teacher is holding the class at "{ $step }": wait before going on.
class-paused-notice = Look up here: your teacher paused every tank.
class-revealed = The class's predictions:
class-refused = The class server refused your { $kind }: { $reason }
class-ended = The class cannot be reached: { $reason }
class-unknown-lesson = This version of Shoal cannot open the class's lesson ({ $lesson }).
