# Arrows over a physical fish (src/ui/body_overlay.rs).

overlay-wants-to-go = wants to go
overlay-goes = goes
overlay-current = current

# Saving and opening files (src/ui/files.rs).

files-download-failed = The download did not start: { $reason }
files-write-failed = Could not save { $name }: { $reason }
files-dialog-failed = The file dialog did not open: { $reason }
files-read-failed = could not read { $name }: { $reason }
files-downloading-next = Downloading { $name }: { $next }.
files-downloading = Downloading { $name }.
files-saved = Saved { $name } in the folder Shoal was started from.

# The Seeing view options (src/ui/seeing.rs).

seeing-started-paused = Reduced motion is on (this computer asks for it, or the link does): the fish wait, paused, until you press Play (or Space). View → Reduce motion turns it off.
seeing-high-contrast = High contrast
    .help = White text on black, strong borders round every control and a thick yellow ring round the one the keyboard is on: easier to read on a washed-out projector or for weak eyes
seeing-reduce-motion = Reduce motion
    .help = Calmer pictures for anyone whom movement on screen bothers: the light on the sand stops shimmering, a camera following a fish moves only when the fish nears the edge, and panels open without sliding. The fish still swim: Pause (Space) stops them
