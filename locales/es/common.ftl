# Palabras que se usan en toda la interfaz.

fish-count = { $count ->
    [one] { $count } pez
   *[other] { $count } peces
}
polarization-reading = polarización { $value }
language = Idioma
    .help = El idioma de todas las palabras de Shoal. Viaja en los enlaces que compartes.
