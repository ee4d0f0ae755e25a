package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The CLI's progress bar forced on ({@code --progress}, stderr not being a terminal here): a bar per stage, read and
 * write included, each ending full; the picture is the one written without it; {@code -q} and the default on a
 * pipe print none.
 */
class ProgressBarTest {

    private static final String BT = "testdata/dem/bigtujunga_srtm30m_utm11n.tif";

    @TempDir
    Path dir;

    @Test
    void forcedProgressNamesEveryStageAndEndsEachFull() throws Exception {
        Path bar = dir.resolve("bar.png");
        CliRun run = CliRun.of("render", BT, "-o", bar.toString(), "--shadows", "sweep", "--progress");
        assertEquals(0, run.exitCode(), run.err());
        for (String stage : new String[] {"read", "shadows", "shading", "write"}) {
            Matcher full = Pattern.compile("(?m)^" + stage + " +100% .*? (\\d+)/(\\d+)").matcher(run.err());
            assertTrue(full.find(), stage + " ends full in:\n" + run.err());
            assertEquals(full.group(2), full.group(1), stage);
        }
        assertTrue(run.err().indexOf("read ") < run.err().indexOf("write "), "read comes before write");

        Path plain = dir.resolve("plain.png");
        CliRun quiet = CliRun.of("render", BT, "-o", plain.toString(), "--shadows", "sweep");
        assertEquals(0, quiet.exitCode(), quiet.err());
        assertFalse(quiet.err().contains("100%"), "no bar on a pipe unless forced: " + quiet.err());
        assertArrayEquals(Files.readAllBytes(plain), Files.readAllBytes(bar), "the bar changed the picture");

        CliRun both = CliRun.of("render", BT, "-o", plain.toString(), "--progress", "-q");
        assertEquals(0, both.exitCode(), both.err());
        assertFalse(both.err().contains("100%"), "-q wins: " + both.err());
    }
}
