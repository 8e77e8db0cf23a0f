# Words used across the interface.

fish-count = { $count ->
    [one] { $count } fish
   *[other] { $count } fish
}
polarization-reading = polarization { $value }
language = Language
    .help = The language of every word Shoal shows. It travels in the links you share.
