package io.github.jdem846.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.geo.CrsInfo;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.condition.DisabledOnOs;
import org.junit.jupiter.api.condition.OS;
import org.junit.jupiter.api.io.TempDir;

/**
 * A FIFO without a writer, a device or a directory, given as the DEM or met as its sidecar, is refused (or, for
 * an optional .prj, passed over with a notice) before anything opens it: opening a FIFO for reading blocks until
 * someone writes. Each test has a timeout, so a regression fails instead of hanging the build. FIFOs are made with
 * {@code mkfifo}, which Windows has not.
 */
@Timeout(value = 20, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class NonRegularFileTest {

    private static final String HEADER =
            "ncols 3\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -9999\nbyteorder LSBFIRST\n";

    @TempDir
    Path tmp;

    private Path fifo(String name) throws IOException, InterruptedException {
        Path p = tmp.resolve(name);
        Process mk = new ProcessBuilder("mkfifo", p.toString()).redirectErrorStream(true).start();
        assertEquals(0, mk.waitFor(), new String(mk.getInputStream().readAllBytes()));
        assertTrue(Files.exists(p) && !Files.isRegularFile(p), "mkfifo made " + p);
        return p;
    }

    /** read, inspect and statistics each refuse {@code file} with a message naming {@code named} and parts. */
    private static void assertRefused(Path file, Path named, String... parts) {
        for (ThrowingRead read : new ThrowingRead[] {DemReader::read, DemReader::inspect, DemReader::statistics}) {
            DemFormatException e = assertThrows(DemFormatException.class, () -> read.apply(file));
            String m = e.getMessage();
            assertTrue(m.startsWith(named.toString() + ": "), m);
            for (String part : parts) {
                assertTrue(m.contains(part), "'" + part + "' missing in: " + m);
            }
        }
    }

    @FunctionalInterface
    private interface ThrowingRead {
        Object apply(Path file) throws IOException;
    }

    @Test
    @DisabledOnOs(OS.WINDOWS)
    void aFifoGivenAsTheDemIsRefusedWithoutOpeningIt() throws Exception {
        for (String name : new String[] {"pipe.tif", "pipe.asc", "pipe.flt", "pipe"}) {
            Path p = fifo(name);
            assertRefused(p, p, "is a FIFO (named pipe), not a regular file", "a DEM must be a regular file");
        }
    }

    @Test
    @DisabledOnOs(OS.WINDOWS)
    void aFifoGivenAsTheHeaderItselfIsRefused() throws Exception {
        Files.write(tmp.resolve("g.flt"), new byte[24]);
        Path hdr = fifo("g.hdr");
        assertRefused(hdr, hdr, "is a FIFO (named pipe)");
    }

    @Test
    @DisabledOnOs(OS.WINDOWS)
    void aFifoHeaderBesideAGridFloatIsRefused() throws Exception {
        Path flt = tmp.resolve("g.flt");
        Files.write(flt, new byte[24]);
        Path hdr = fifo("g.hdr");
        assertRefused(flt, hdr, "is a FIFO (named pipe), not a regular file", "a header must be a regular file");
    }

    @Test
    @DisabledOnOs(OS.WINDOWS)
    void aFifoHeaderBesideABilIsRefused() throws Exception {
        Path bil = tmp.resolve("b.bil");
        Files.write(bil, new byte[6]);
        Path hdr = fifo("b.hdr");
        assertRefused(bil, hdr, "is a FIFO (named pipe)");
    }

    @Test
    @DisabledOnOs(OS.WINDOWS)
    void aFifoPrjIsPassedOverWithANotice() throws Exception {
        Path flt = tmp.resolve("p.flt");
        Files.write(flt, new byte[24]);
        Files.writeString(tmp.resolve("p.hdr"), HEADER);
        fifo("p.prj");
        DemInfo info = DemReader.inspect(flt);
        assertEquals(CrsInfo.UNKNOWN, info.geometry().crs());
        assertTrue(info.notices().contains("p.prj is a FIFO (named pipe), not a regular file, and was not read, so"
                + " the CRS is unknown"), info.notices().toString());
        assertEquals(6, DemReader.read(flt).statistics().validCount());

        Path asc = tmp.resolve("q.asc");
        Files.writeString(asc, HEADER + "1 2 3\n4 5 6\n");
        fifo("q.prj");
        assertTrue(DemReader.inspect(asc).notices().get(0).startsWith("q.prj is a FIFO"));
    }

    @Test
    @DisabledOnOs(OS.WINDOWS)
    void aCharacterDeviceIsRefused() {
        Path devNull = Path.of("/dev/null");
        assertRefused(devNull, devNull, "is a character device, not a regular file");
    }

    @Test
    void aDirectoryIsRefused() throws IOException {
        Path d = Files.createDirectory(tmp.resolve("dem.tif"));
        assertRefused(d, d, "is a directory, not a DEM file");
    }

    @Test
    void aDirectoryNamedLikeTheHeaderIsRefused() throws IOException {
        Path flt = tmp.resolve("d.flt");
        Files.write(flt, new byte[24]);
        Path hdr = Files.createDirectory(tmp.resolve("d.hdr"));
        assertRefused(flt, hdr, "is a directory, not a regular file");
    }
}
