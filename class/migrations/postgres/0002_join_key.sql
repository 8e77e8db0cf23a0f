-- A join can be resent safely: the client's join key (random, one per join),
-- stored as its SHA-256 hash, finds the student it already made.
ALTER TABLE students ADD COLUMN join_key_hash TEXT;
CREATE UNIQUE INDEX students_join_key ON students(class_code, join_key_hash);
