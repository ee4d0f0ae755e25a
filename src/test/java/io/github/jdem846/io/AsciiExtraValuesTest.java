package io.github.jdem846.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.raster.Dem;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Values after an ESRI ASCII grid's nrows × ncols are ignored, and a read that reaches the last row says so in
 * the notices of what it returns (a header whose nrows or ncols is too small was silently accepted).
 */
class AsciiExtraValuesTest {

    private static final String HEADER = "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n";

    @TempDir
    Path tmp;

    private Path asc(String values) throws IOException {
        Path p = tmp.resolve("grid.asc");
        Files.writeString(p, HEADER + values);
        return p;
    }

    private static boolean mentionsExtraValues(DemInfo info) {
        return info.notices().stream().anyMatch(n -> n.contains("after the grid's nrows × ncols"));
    }

    @Test
    void extraValuesAreIgnoredWithANotice() throws IOException {
        LoadedDem loaded = DemReader.load(asc("1 2 3\n4 5 6\n7 8\n"), ReadRequest.FULL);
        assertTrue(loaded.info().notices().contains("2 values after the grid's nrows × ncols = 2 × 3 were ignored"
                + " (is the header's nrows or ncols too small?)"), loaded.info().notices().toString());
        Dem dem = loaded.dem();
        assertEquals(6, dem.get(2, 1));
        assertEquals(6, dem.statistics().max());

        LoadedDem one = DemReader.load(asc("1 2 3 4 5 6 junk"), ReadRequest.FULL);
        assertTrue(one.info().notices().contains("1 value after the grid's nrows × ncols = 2 × 3 were ignored"
                + " (is the header's nrows or ncols too small?)"), one.info().notices().toString());
    }

    @Test
    void aGridOfExactlyNrowsTimesNcolsHasNoNotice() throws IOException {
        assertFalse(mentionsExtraValues(DemReader.load(asc("1 2 3\n4 5 6\n\n  \n"), ReadRequest.FULL).info()));
    }

    @Test
    void windowsReachingTheLastRowCountTheRest() throws IOException {
        Path p = asc("1 2 3\n4 5 6\n7\n");
        assertTrue(mentionsExtraValues(DemReader.load(p, ReadRequest.of(Window.cells(1, 1, 2, 1))).info()));
        // a window above the last row does not read so far
        assertFalse(mentionsExtraValues(DemReader.load(p, ReadRequest.of(Window.cells(0, 0, 3, 1))).info()));
        assertTrue(mentionsExtraValues(DemReader.load(p, ReadRequest.decimated(2)).info()));
    }
}
