<?php
// A class's quiz in a real Moodle, for `grafika check --moodle-responses`
// (docs/contributing.md, "Re-marking a Moodle quiz"). Not part of Moodle:
// run it with the PHP of a Moodle installed for testing, never on a live
// site.
//
//   php responses.php --moodle=MOODLE_ROOT --file=quiz.xml [--students=30]
//
// It creates a course with its default question bank, imports FILE there
// with Moodle's own importer ("Get category from file" on), enrols
// --students students (fake names), makes a quiz with one random slot per
// problem category (grafika/<topic>/<NN>), each slot's maximum mark the
// marks its statement states (as README has the lecturer set them), and
// submits one attempt per student through the quiz attempt API
// (quiz_attempt, the question usage), the deferred feedback behaviour, as
// the attempt page posts them. Student k answers by
// the pattern k mod 8:
//
//   0 right: each blank's first 100 % answer as Moodle shows it
//   1 rounded: each number to 4 significant figures
//   2 decimal commas: each number with a comma (an English Moodle reads
//     0,8 as 8: its blanks are marked wrong)
//   3 a catalog mistake: in every blank that has a 0 % answer naming the
//     first mistake of the question's first such blank, that answer (the
//     mistake carried through, so Moodle marks the later blanks wrong)
//   4 an empty blank (the second) and free text in a number blank (the
//     first): "tidak tahu"
//   5 right, with the Unicode minus − in negative numbers
//   6 the mistake of 3 in the first blank only, the rest right
//   7 right
//
// and the last student leaves the attempt unfinished. It prints one JSON
// line: {"course": id, "quiz": id, "students": n,
// "attempts": n, "finished": n, "grade_item": id}.
//
//   php responses.php --moodle=MOODLE_ROOT --download=csv|json|excel|ods --course=ID [--lang=id] > FILE
//
// writes the course's quiz's Responses report to standard output as the
// report's own "Download table data as" does (the last try, the question
// text and the response of each slot), in the site's language or --lang's
// (its language pack installed: `id` writes the columns in Indonesian).
//
//   php responses.php --moodle=MOODLE_ROOT --import=GRADES.csv --course=ID
//
// imports a grades CSV into the course's gradebook with Moodle's own CSV
// import (grade/import/csv: the students matched by their email address,
// the column "grafika" mapped to the quiz's grade item) and prints each
// student's grade read back, one JSON line each:
// {"email": …, "grade": …}.

define('CLI_SCRIPT', true);

$opts = getopt('', ['moodle:', 'file::', 'students::', 'import::', 'course::', 'column::', 'download::', 'lang::']);
if (empty($opts['moodle']) || (empty($opts['file']) && empty($opts['import']) && empty($opts['download']))) {
    fwrite(STDERR, "usage: php responses.php --moodle=MOODLE_ROOT --file=QUIZ.xml [--students=30]\n"
        . "       php responses.php --moodle=MOODLE_ROOT --download=csv|json|excel|ods --course=ID [--lang=id] > FILE\n"
        . "       php responses.php --moodle=MOODLE_ROOT --import=GRADES.csv --course=ID [--column=grafika]\n");
    exit(2);
}
$run = (object) [];
$run->file = isset($opts['file']) ? realpath($opts['file']) : null;
$run->download = $opts['download'] ?? null;
$run->lang = $opts['lang'] ?? null;
$run->students = (int) ($opts['students'] ?? 30);
$run->import = isset($opts['import']) ? realpath($opts['import']) : null;
$run->course = (int) ($opts['course'] ?? 0);
$run->column = $opts['column'] ?? 'grafika';

require($opts['moodle'] . '/config.php');
require_once($CFG->libdir . '/questionlib.php');
require_once($CFG->dirroot . '/course/lib.php');
require_once($CFG->dirroot . '/question/format/xml/format.php');
require_once($CFG->dirroot . '/mod/quiz/locallib.php');
require_once($CFG->dirroot . '/mod/quiz/report/reportlib.php');
require_once($CFG->dirroot . '/mod/quiz/report/responses/report.php');
require_once($CFG->libdir . '/testing/classes/util.php');
require_once($CFG->libdir . '/gradelib.php');

\core\session\manager::set_user(get_admin());

/** One JSON line. */
function out(array $line): void {
    echo json_encode($line, JSON_UNESCAPED_UNICODE | JSON_UNESCAPED_SLASHES), "\n";
}

if ($run->import) {
    import_grades($run);
    exit(0);
}
if ($run->download) {
    download($run);
    exit(0);
}

$gen = testing_util::get_data_generator();
$tag = uniqid();
$course = create_course((object) [
    'fullname' => 'grafika responses ' . basename($run->file),
    'shortname' => 'grafika-r-' . $tag,
    'category' => $DB->get_field_select('course_categories', 'MIN(id)', '1 = 1'),
]);
$bank = \core_question\local\bank\question_bank_helper::get_default_open_instance_system_type($course, true);
$context = context_module::instance($bank->id);
$top = question_get_default_category($context->id, true);

$qformat = new qformat_xml();
$qformat->setCategory($top);
$qformat->setContexts([$context]);
$qformat->setCourse($course);
$qformat->setFilename($run->file);
$qformat->setRealfilename(basename($run->file));
$qformat->setMatchgrades('error');
$qformat->setCatfromfile(true);
$qformat->setContextfromfile(false);
$qformat->setStoponerror(true);
ob_start();
$ok = $qformat->importpreprocess() && $qformat->importprocess() && $qformat->importpostprocess();
$log = trim(html_to_text(ob_get_clean(), 0, false));
if (!$ok) {
    fwrite(STDERR, "import failed: $log\n");
    exit(1);
}

// The categories of the questions imported, in the file's order: one per
// problem (grafika/<topic>/<NN>), each holding the problem's variants.
$categories = [];
$marks = [];
foreach ($qformat->questionids as $qid) {
    $q = question_bank::load_question_data($qid);
    if (!isset($categories[$q->category])) {
        $categories[$q->category] = count($categories);
        // The marks the statement states, as README tells the lecturer
        // to set them: a Cloze's default mark is the sum of its blanks'
        // weights, not its marks.
        $stated = preg_match_all('/\\((\\d+) (?:marks?|poin)\\)/', html_to_text($q->questiontext, 0, false), $m)
            ? (float) end($m[1]) : (float) $q->defaultmark;
        $marks[$q->category] = $stated;
    }
}

$quiz = $gen->create_module('quiz', [
    'course' => $course->id,
    'name' => 'grafika quiz',
    'questionsperpage' => 0,
    'grade' => 100,
    'preferredbehaviour' => 'deferredfeedback',
]);
$quizobj = \mod_quiz\quiz_settings::create($quiz->id);
$structure = $quizobj->get_structure();
foreach (array_keys($categories) as $catid) {
    $structure->add_random_questions(1, 1, ['filter' => ['category' => [
        'jointype' => \core_question\local\bank\condition::JOINTYPE_DEFAULT,
        'values' => [$catid],
        'filteroptions' => ['includesubcategories' => false],
    ]]]);
}
// Each slot's maximum mark: the problem's stated marks (a random slot
// gets 1).
$quizobj = \mod_quiz\quiz_settings::create($quiz->id);
$structure = $quizobj->get_structure();
foreach ($structure->get_slots() as $slot) {
    $filter = $DB->get_field('question_set_references', 'filtercondition', ['itemid' => $slot->id]);
    $catid = (int) json_decode($filter, true)['filter']['category']['values'][0];
    $structure->update_slot_maxmark($slot, $marks[$catid]);
}
$quizobj->get_grade_calculator()->recompute_quiz_sumgrades();

$firsts = ['Siti', 'Budi', 'Dewi', 'Agus', 'Rina', 'Joko', 'Putri', 'Andi', 'Wati', 'Eko'];
$lasts = ['Rahayu', 'Santoso', 'Lestari', 'Wijaya', 'Kurniawan', 'Hidayat', 'Saputra', 'Nugroho'];
$finished = 0;
for ($k = 0; $k < $run->students; $k++) {
    $first = $firsts[$k % count($firsts)];
    $last = $lasts[intdiv($k, count($firsts)) % count($lasts)] . ($k >= 80 ? " $k" : '');
    // One fake name with a CSV formula, one with a comma and quotes.
    if ($k == 4) {
        $last = '=HYPERLINK("x")';
    } else if ($k == 5) {
        $first = 'Ni "Made", Ayu';
    }
    $user = $gen->create_user([
        'firstname' => $first, 'lastname' => $last,
        'email' => sprintf('student%03d.%s@example.edu', $k + 1, $tag),
        'idnumber' => sprintf('S%03d', $k + 1),
    ]);
    $gen->enrol_user($user->id, $course->id, 'student');
    \core\session\manager::set_user($user);
    $quizobj = \mod_quiz\quiz_settings::create($quiz->id, $user->id);
    $attempt = quiz_prepare_and_start_new_attempt($quizobj, 1, null);
    $attemptobj = \mod_quiz\quiz_attempt::create($attempt->id);
    $post = ['slots' => implode(',', $attemptobj->get_slots())];
    foreach ($attemptobj->get_slots() as $slot) {
        $qa = $attemptobj->get_question_attempt($slot);
        $post[$qa->get_control_field_name('sequencecheck')] = $qa->get_sequence_check_count();
        foreach (responses($qa->get_question(), $k % 8) as $i => $typed) {
            $post[$qa->get_qt_field_name("sub{$i}_answer")] = $typed;
        }
    }
    $attemptobj->process_submitted_actions(time(), false, $post);
    if ($k < $run->students - 1) {
        $attemptobj->process_submit(time(), false);
        $attemptobj->process_grade_submission(time());
        $finished++;
    }
    \core\session\manager::set_user(get_admin());
}

/** A number to n significant figures, as a string with a point. */
function sig(string $x, int $n): string {
    $v = (float) $x;
    if ($v == 0.0) {
        return '0';
    }
    $e = (int) floor(log10(abs($v)));
    return (string) round($v, $n - 1 - $e);
}

/** The mistake a 0 % answer's feedback names (its first). */
function mistake_of(string $feedback): string {
    return trim(explode('(', preg_replace('/^.*?:\s*/', '', strip_tags($feedback)))[0]);
}

/** What student pattern $p types in each blank of Cloze question $q. */
function responses(question_definition $q, int $p): array {
    $typed = [];
    $mistake = null;
    foreach ($q->subquestions as $i => $b) {
        $right = null;
        $wrong = [];
        foreach ($b->answers as $a) {
            if ((float) $a->fraction >= 1.0 && $right === null) {
                $right = $a->answer;
            } else if ((float) $a->fraction == 0.0) {
                $wrong[mistake_of($a->feedback)] = $a->answer;
            }
        }
        $number = $b instanceof qtype_numerical_question;
        $t = $right;
        if ($number && $p == 1) {
            $t = sig($right, 4);
        } else if ($number && $p == 2) {
            $t = str_replace('.', ',', $right);
        } else if ($number && $p == 5) {
            $t = str_replace('-', '−', $right);
        } else if ($p == 3 || ($p == 6 && $mistake === null)) {
            if ($mistake === null && $wrong) {
                $mistake = array_key_first($wrong);
                $t = $wrong[$mistake];
            } else if ($p == 3 && $mistake !== null && isset($wrong[$mistake])) {
                $t = $wrong[$mistake];
            }
        } else if ($p == 4 && $i == 1 && $number) {
            $t = 'tidak tahu';
        } else if ($p == 4 && $i == 2) {
            $t = '';
        }
        $typed[$i] = $t;
    }
    return $typed;
}

$item = grade_item::fetch(['itemtype' => 'mod', 'itemmodule' => 'quiz', 'iteminstance' => $quiz->id,
    'courseid' => $course->id]);
out(['course' => (int) $course->id, 'quiz' => (int) $quiz->id, 'students' => $run->students,
    'attempts' => $run->students, 'finished' => $finished, 'grade_item' => (int) $item->id]);

/**
 * The Responses report (last try, enrolled users with attempts, the
 * question text and the response of each slot) as its "Download table data
 * as" button writes it: the report's own display() with download=FORMAT,
 * to standard output (the download ends the script, as it ends the web
 * request).
 */
function download(object $run): void {
    global $DB, $PAGE;
    $course = get_course($run->course);
    $quiz = $DB->get_record('quiz', ['course' => $course->id], '*', IGNORE_MULTIPLE);
    $cm = get_coursemodule_from_instance('quiz', $quiz->id, $course->id);
    $_GET = ['download' => $run->download, 'attempts' => 'enrolled_with', 'whichtries' => 'last',
        'qtext' => 1, 'resp' => 1, 'right' => 0, 'id' => $cm->id, 'mode' => 'responses'];
    if ($run->lang) {
        force_current_language($run->lang);
    }
    $PAGE = new moodle_page();
    $PAGE->set_context(context_module::instance($cm->id));
    $PAGE->set_cm($cm, $course);
    $PAGE->set_url('/mod/quiz/report.php', ['id' => $cm->id, 'mode' => 'responses']);
    $report = new quiz_responses_report();
    $report->display($quiz, $cm, $course);
}

/** Imports the grades CSV with grade/import/csv's own code, reads the grades back. */
function import_grades(object $run): void {
    global $CFG, $DB;
    require_once($CFG->dirroot . '/grade/lib.php');
    require_once($CFG->dirroot . '/grade/import/lib.php');
    require_once($CFG->libdir . '/csvlib.class.php');
    $course = get_course($run->course);
    $quiz = $DB->get_record('quiz', ['course' => $course->id], '*', IGNORE_MULTIPLE);
    $item = grade_item::fetch(['itemtype' => 'mod', 'itemmodule' => 'quiz', 'iteminstance' => $quiz->id,
        'courseid' => $course->id]);
    $text = file_get_contents($run->import);
    $importcode = get_new_importcode();
    $csv = new gradeimport_csv_load_data();
    $csv->load_csv_content($text, "UTF-8", "comma", 0);
    $header = $csv->get_headers();
    if ($csv->get_error()) {
        fwrite(STDERR, 'import: ' . $csv->get_error() . "\n");
        exit(1);
    }
    $email = array_search('Email address', $header);
    $grade = array_search($run->column, $header);
    $form = (object) ['mapfrom' => $email, 'mapto' => 'useremail', 'id' => $course->id,
        'importcode' => $importcode, 'forceimport' => false];
    foreach ($header as $i => $h) {
        $form->{"mapping_$i"} = $i == $grade ? $item->id : '0';
    }
    $reader = new csv_import_reader($csv->get_iid(), "grade");
    $ok = $csv->prepare_import_grade_data($header, $form, $reader, $course->id, 0, 0, 0);
    if (!$ok) {
        fwrite(STDERR, 'import: ' . implode('; ', $csv->get_gradebookerrors()) . "\n");
        exit(1);
    }
    ob_start();
    $done = grade_import_commit($course->id, $importcode, false, false);
    $log = trim(html_to_text(ob_get_clean(), 0, false));
    if (!$done) {
        fwrite(STDERR, "import: $log\n");
        exit(1);
    }
    $grades = grade_get_grades($course->id, 'mod', 'quiz', $quiz->id,
        array_keys(get_enrolled_users(context_course::instance($course->id), '', 0, 'u.id')));
    foreach ($grades->items[0]->grades as $uid => $g) {
        out(['email' => $DB->get_field('user', 'email', ['id' => $uid]), 'grade' => $g->grade]);
    }
}
