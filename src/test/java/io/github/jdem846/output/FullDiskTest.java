package io.github.jdem846.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.google.common.jimfs.Configuration;
import com.google.common.jimfs.Jimfs;
import io.github.jdem846.job.JobListener;
import io.github.jdem846.job.ReliefJob;
import io.github.jdem846.render.Scene;
import io.github.jdem846.testing.TestDems;
import io.github.jdem846.tiles.TileJob;
import io.github.jdem846.tiles.ZoomRange;
import java.io.IOException;
import java.nio.file.FileSystem;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A disk that fills up while a picture or a tile pyramid is written: the write fails with one {@link IOException}
 * whose message names the output file and says what the file system said, and nothing is left in the directory
 * (no partial image, no hidden temporary file, no sidecar). The "disk" is an in-memory file system (Jimfs) with a
 * size limit far below what the output needs, so the writers run out of space part-way, on any machine.
 */
class FullDiskTest {

    private static final Path BT = Path.of("testdata/dem/bigtujunga_srtm30m_utm11n.tif");
    /** Far below the 1197 × 643 pictures (about 1 MB as PNG, 0.8–3 MB as GeoTIFF) and the tiles. */
    private static final long DISK_BYTES = 64 * 1024;

    private static FileSystem smallDisk() {
        return Jimfs.newFileSystem(Configuration.unix().toBuilder().setMaxSize(DISK_BYTES).setBlockSize(4096)
                .build());
    }

    private static List<Path> contents(Path dir) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            return s.filter(p -> !p.equals(dir)).toList();
        }
    }

    private static void assertNamedAndNothingLeft(IOException e, Path out, Path dir) throws IOException {
        String m = e.getMessage();
        assertTrue(m.contains(out.toString()), "names " + out + ": " + m);
        assertFalse(m.contains("Exception"), "no exception's name: " + m);
        assertEquals(1, m.lines().count(), "one line: " + m);
        assertEquals(List.of(), contents(dir), "nothing left in " + dir);
    }

    @ParameterizedTest
    @ValueSource(strings = {"relief.png", "relief.tif"})
    void aReliefJobOnAFullDiskFailsNamingTheFileAndLeavesNothing(String name) throws IOException {
        try (FileSystem disk = smallDisk()) {
            Path dir = Files.createDirectories(disk.getPath("/out"));
            Path out = dir.resolve(name);
            ReliefJob job = ReliefJob.of(BT);
            IOException e = assertThrows(IOException.class, () -> job.runAndWrite(out,
                    WriteOptions.defaults().withSidecars(WriteOptions.Sidecars.ALWAYS), JobListener.NONE));
            assertNamedAndNothingLeft(e, out, dir);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"gray.png", "gray.tif"})
    void anImageWrittenAtOnceOnAFullDiskLeavesNothing(String name) throws IOException {
        var dem = TestDems.load(TestDems.BIG_TUJUNGA);
        byte[] gray = new byte[dem.width() * dem.height()];
        for (int i = 0; i < gray.length; i++) {
            gray[i] = (byte) (Float.isNaN(dem.get(i % dem.width(), i / dem.width())) ? 0
                    : dem.get(i % dem.width(), i / dem.width()));   // incompressible enough to need the space
        }
        try (FileSystem disk = smallDisk()) {
            Path dir = Files.createDirectories(disk.getPath("/out"));
            Path out = dir.resolve(name);
            IOException e = assertThrows(IOException.class, () -> ImageOutput.writeGray(out, gray, dem.width(),
                    dem.height(), GeoReference.of(dem.geometry()), WriteOptions.defaults()));
            assertNamedAndNothingLeft(e, out, dir);
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"tiles", "relief.pmtiles"})
    void aTilePyramidOnAFullDiskLeavesNothing(String name) throws IOException {
        try (FileSystem disk = smallDisk()) {
            Path dir = Files.createDirectories(disk.getPath("/out"));
            Path out = dir.resolve(name);
            TileJob job = TileJob.of(BT, new ZoomRange(9, 12)).withScene(Scene.defaults());
            IOException e = assertThrows(IOException.class, () -> job.run(out, JobListener.NONE));
            assertNamedAndNothingLeft(e, out, dir);
        }
    }
}
