package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Bad usage exits with status 2 and says so in one line naming the option, the value and what is allowed, plus at
 * most a hint line; never the usage text, never an exception's name, and no output file.
 */
class UsageErrorTest {

    private static final String BT = "testdata/dem/bigtujunga_srtm30m_utm11n.tif";

    @TempDir
    Path dir;

    /**
     * Runs {@code command FILE -o OUT args}, expects a usage error whose first line contains every one of
     * {@code mentions}.
     */
    private void assertUsageError(String command, List<String> args, List<String> mentions) {
        Path out = dir.resolve("out.png");
        String[] all = Stream.concat(Stream.of(command, BT, "-o", out.toString(), "-q"), args.stream())
                .toArray(String[]::new);
        CliRun run = CliRun.of(all);
        String what = String.join(" ", all);
        assertUsage(run, what, mentions);
        assertFalse(Files.exists(out), what + ": no output file");
    }

    /** Exit status 2, one line (and at most a hint) containing {@code mentions}, no exception, nothing on stdout. */
    static void assertUsage(CliRun run, String what, List<String> mentions) {
        String err = run.err();
        assertEquals(2, run.exitCode(), what + ": " + err);
        assertFalse(err.contains("Exception"), what + ": no exception name: " + err);
        assertFalse(err.contains("Usage:"), what + ": no usage text: " + err);
        List<String> lines = err.lines().toList();
        assertTrue(lines.size() >= 1 && lines.size() <= 2, what + ": one line and a hint: " + err);
        assertTrue(lines.get(0).startsWith("jdem846: "), what + ": " + err);
        for (String m : mentions) {
            assertTrue(lines.get(0).contains(m), what + ": the message mentions '" + m + "': " + err);
        }
        if (lines.size() == 2) {
            assertTrue(lines.get(1).endsWith("--help'."), what + ": the hint: " + err);
        }
        assertEquals("", run.out(), what);
    }

    static Stream<Arguments> parseErrors() {
        return Stream.of(
                Arguments.of("render", List.of("--no-such-option"), List.of("--no-such-option")),
                Arguments.of("render", List.of("--width"), List.of("--width")),
                Arguments.of("render", List.of("--width", "abc"), List.of("--width", "abc")),
                Arguments.of("hillshade", List.of("--z-factor", "lots"), List.of("--z-factor", "lots")),
                Arguments.of("shadows", List.of("--threads", "1.5"), List.of("--threads", "1.5")));
    }

    @ParameterizedTest(name = "{0} {1}")
    @MethodSource("parseErrors")
    void parseErrorsGiveOneLineAndAHint(String command, List<String> args, List<String> mentions) {
        assertUsageError(command, args, mentions);
    }
}
