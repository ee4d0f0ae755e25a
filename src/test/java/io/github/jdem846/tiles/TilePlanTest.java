package io.github.jdem846.tiles;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import io.github.jdem846.job.JobListener;
import io.github.jdem846.raster.ElevationStatistics;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A plan's groups rendered apart, in any order, by a second plan prepared from the job and the first plan's range
 * (as a cluster's workers do) give the same tiles as {@link TileJob#run}, byte for byte, and the same PMTiles
 * archive; the groups cover every tile of every zoom once; the units shipped between processes survive Java
 * serialization.
 */
class TilePlanTest {

    @TempDir
    Path dir;

    @Test
    void groupsRenderedApartInAnyOrderMakeTheSameArchive() throws Exception {
        TileJob job = TileJobTest.job();
        Path whole = dir.resolve("whole.pmtiles");
        job.run(whole, JobListener.NONE);

        TilePlan driver = TilePlan.prepare(job, JobListener.NONE);
        TilePlan worker = TilePlan.prepare(job, roundTrip(driver.range()));
        List<TileGroup> groups = new ArrayList<>(driver.groups());
        Collections.shuffle(groups, new Random(846));
        Path parts = dir.resolve("parts.pmtiles");
        try (TileSink sink = TileSink.open(parts)) {
            for (TileGroup g : groups) {
                for (EncodedTile t : worker.render(roundTrip(g))) {
                    EncodedTile shipped = roundTrip(t);
                    sink.write(shipped.tile(), shipped.png());
                }
            }
            sink.commit(driver.tileSetInfo());
        }
        assertArrayEquals(Files.readAllBytes(whole), Files.readAllBytes(parts));
    }

    @Test
    void aGroupGivesTheSameTilesAsTheDirectoryRun() throws Exception {
        TileJob job = TileJobTest.job();
        Path whole = dir.resolve("whole");
        job.run(whole, JobListener.NONE);
        TilePlan plan = TilePlan.prepare(job, JobListener.NONE);
        int compared = 0;
        for (TileGroup g : plan.groups()) {
            for (EncodedTile t : plan.render(g)) {
                Path file = whole.resolve(t.tile().z() + "/" + t.tile().x() + "/" + t.tile().y() + ".png");
                assertArrayEquals(Files.readAllBytes(file), t.png(), t.tile().toString());
                compared++;
            }
        }
        try (var files = Files.walk(whole)) {
            assertEquals(files.filter(Files::isRegularFile).count(), compared, "every written tile compared");
        }
        assertTrue(compared > 20, "a pyramid of several zooms: " + compared);
    }

    @Test
    void groupsCoverEveryTileOnce() throws IOException {
        TilePlan plan = TilePlan.prepare(TileJobTest.job(), JobListener.NONE);
        Set<WebMercatorTile> seen = new HashSet<>();
        long count = 0;
        for (TileGroup g : plan.groups()) {
            assertTrue(g.size() <= TilePlan.GROUP * TilePlan.GROUP, g.toString());
            assertEquals(g.size(), g.tiles().size());
            for (WebMercatorTile t : g.tiles()) {
                assertTrue(seen.add(t), "tile " + t + " in two groups");
                count++;
            }
        }
        assertEquals(plan.tileCount(), count);
        assertEquals(TileJobTest.ZOOMS.max(), plan.groups().get(0).z(), "the deepest zoom first");
    }

    @Test
    void refusesGroupsThatAreNotItsOwn() throws IOException {
        TilePlan plan = TilePlan.prepare(TileJobTest.job(), JobListener.NONE);
        assertThrows(IllegalArgumentException.class, () -> plan.render(new TileGroup(3, 0, 0, 1, 1)));
        TileGroup first = plan.groups().get(0);
        assertThrows(IllegalArgumentException.class, () -> plan.render(
                new TileGroup(first.z(), 0, 0, 0, 0)));
        assertThrows(IllegalArgumentException.class, () -> TilePlan.prepare(TileJobTest.job(),
                new ElevationStatistics(Double.NaN, Double.NaN, 0, 10)));
    }

    @SuppressWarnings("unchecked")
    private static <T> T roundTrip(T value) throws IOException, ClassNotFoundException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(value);
        }
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
            return (T) in.readObject();
        }
    }
}
