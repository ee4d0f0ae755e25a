package io.github.jdem846.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Which argument the start-up warm-up takes for the input DEM; it must never fail, whatever the arguments. */
class InputWarmUpTest {

    private static final String JACKSBORO = "testdata/dem/jacksboro_srtm3s_wgs84.tif";
    private static final String BT_FLT = "testdata/dem/bigtujunga_srtm30m_utm11n.flt";

    @TempDir
    Path dir;

    @Test
    void theFirstArgumentThatIsADemIsRead() throws IOException {
        Path colours = dir.resolve("colours.txt");
        Files.writeString(colours, "0 0 0 0\n100 255 255 255\n");
        Path oldOutput = dir.resolve("old.png");
        Files.write(oldOutput, new byte[] {(byte) 0x89, 'P', 'N', 'G'});
        assertEquals(Optional.of(Path.of(JACKSBORO)), InputWarmUp.readFirstDem(new String[] {"tint", "--tint",
            colours.toString(), JACKSBORO, "-o", oldOutput.toString()}));
        assertEquals(Optional.of(Path.of(BT_FLT)), InputWarmUp.readFirstDem(new String[] {"hillshade", "-o",
            oldOutput.toString(), "--sun-azimuth=-720", BT_FLT, JACKSBORO}));
    }

    @Test
    void latitudeAndLongitudeAreWarmedOnlyForTheCommandsThatNeedThem() {
        assertTrue(InputWarmUp.needsLatLon(new String[] {"info", JACKSBORO}));
        assertTrue(InputWarmUp.needsLatLon(new String[] {"render", JACKSBORO, "-o", "x.png", "--sun-time",
            "2024-06-21T17:00Z"}));
        assertTrue(InputWarmUp.needsLatLon(new String[] {"shadows", JACKSBORO, "--sun-time=2024-06-21T17:00Z"}));
        assertTrue(InputWarmUp.needsLatLon(new String[] {"hillshade", JACKSBORO, "-o", "x.png", "--world-file"}));
        assertFalse(InputWarmUp.needsLatLon(new String[] {"hillshade", JACKSBORO, "-o", "info"}));
        assertFalse(InputWarmUp.needsLatLon(new String[] {"render", "--sun-azimuth", "300"}));
        assertFalse(InputWarmUp.needsLatLon(new String[0]));
    }

    @Test
    void onlyALargeFileIsReadAheadAndAtMostAQuarterOfIt() throws IOException {
        io.github.jdem846.io.DemInfo bt = io.github.jdem846.io.DemReader.inspect(Path.of(BT_FLT));
        io.github.jdem846.io.Window.Cells first = (io.github.jdem846.io.Window.Cells) InputWarmUp.firstRows(bt)
                .window();
        long perRead = (long) first.width() * first.height();
        assertEquals(0, InputWarmUp.warmUpCells(bt, perRead), "1197 × 643 is read by the command itself");
        assertEquals(1197L * 643 / 4, InputWarmUp.warmUpCells(bt, 1197L * 643 / 16), "16 reads' worth of cells");
        assertEquals(0, InputWarmUp.warmUpCells(bt, 1197L * 643 / 15));
    }

    @Test
    void theGridsMemoryIsTouchedAheadFrom16To256MibAndAnEighthOfTheHeap() throws IOException {
        io.github.jdem846.io.DemInfo bt = io.github.jdem846.io.DemReader.inspect(Path.of(BT_FLT));
        long gib = 1L << 30;
        assertEquals(0, InputWarmUp.gridMemoryToTouch(bt, 6 * gib), "3 MB: mapped by the command itself");
        assertEquals(0, InputWarmUp.touchGridMemory(bt));
        assertEquals(64_000_000L, InputWarmUp.gridMemoryToTouch(ofSize(4000, 4000), 6 * gib));
        assertEquals(0, InputWarmUp.gridMemoryToTouch(ofSize(4000, 4000), 400L << 20), "more than 1/8 of the heap");
        assertEquals(16L << 20, InputWarmUp.gridMemoryToTouch(ofSize(2048, 2048), 6 * gib));
        assertEquals(0, InputWarmUp.gridMemoryToTouch(ofSize(2048, 2047), 6 * gib), "just under 16 MiB");
        assertEquals(256L << 20, InputWarmUp.gridMemoryToTouch(ofSize(8192, 8192), 6 * gib));
        assertEquals(0, InputWarmUp.gridMemoryToTouch(ofSize(8192, 8193), 6 * gib), "above 256 MiB");
        assertEquals(0, InputWarmUp.gridMemoryToTouch(ofSize(100_000, 100_000), Long.MAX_VALUE), "40 GB");
    }

    @Test
    void onlyTheCommandsThatReadTheWholeGridTouchItsMemory() {
        for (String command : new String[] {"hillshade", "render", "tint", "shadows", "skyview"}) {
            assertTrue(InputWarmUp.readsWholeGrid(new String[] {command, BT_FLT, "-o", "x.png"}), command);
        }
        for (String command : new String[] {"info", "tiles", "view", "sun", "--version"}) {
            assertFalse(InputWarmUp.readsWholeGrid(new String[] {command, BT_FLT}), command);
        }
        assertFalse(InputWarmUp.readsWholeGrid(new String[0]));
    }

    private static io.github.jdem846.io.DemInfo ofSize(int w, int h) {
        return new io.github.jdem846.io.DemInfo("x.flt", io.github.jdem846.io.DemFormat.GRIDFLOAT,
                io.github.jdem846.io.SampleType.FLOAT32, 1, io.github.jdem846.raster.GridGeometry.metric(w, h, 30),
                null, java.util.List.of());
    }

    @Test
    void noDemAmongTheArgumentsGivesNothing() {
        assertEquals(Optional.empty(), InputWarmUp.readFirstDem(new String[0]));
        assertEquals(Optional.empty(), InputWarmUp.readFirstDem(new String[] {"render", "-o", "x.png"}));
        assertEquals(Optional.empty(), InputWarmUp.readFirstDem(new String[] {"hillshade", "missing.tif",
            dir.toString(), "\u0000bad", "--window=1,2,3,4"}));
    }
}
