package io.github.jdem846.bench;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.DemResampler;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * The DEMs of the accuracy study: the real DEMs of testdata/dem, a coarse (≈ 210 m) area average of Big Tujunga
 * standing in for a coarse mountain DEM, and the 4000² fractal.
 *
 * @param name        short name used on the command line and in file names
 * @param description one line for the tables
 * @param dem         the elevations
 */
record StudyDem(String name, String description, Dem dem) {

    /** Every name {@link #load} knows, in report order. */
    static final List<String> NAMES = List.of("bigtujunga", "bigtujunga-210m", "jacksboro", "luxembourg",
            "vancouver", "maungawhau", "fractal4000");

    /** Big Tujunga is area-averaged by this factor per axis for the coarse DEM (30 m → ≈ 210 m). */
    static final int COARSE_FACTOR = 7;

    /** Loads DEM {@code name}; real DEMs are read from {@code testdata}/dem. */
    static StudyDem load(String name, Path testdata) throws IOException {
        Path dir = testdata.resolve("dem");
        switch (name) {
            case "bigtujunga":
                return new StudyDem(name, "Big Tujunga SRTM 30 m (UTM 11N)",
                        DemReader.read(dir.resolve("bigtujunga_srtm30m_utm11n.flt")));
            case "bigtujunga-210m": {
                Dem full = DemReader.read(dir.resolve("bigtujunga_srtm30m_utm11n.flt"));
                int w = (int) Math.round((double) full.width() / COARSE_FACTOR);
                int h = (int) Math.round((double) full.height() / COARSE_FACTOR);
                return new StudyDem(name, "Big Tujunga area-averaged to " + w + "×" + h + " (≈ 210 m cells)",
                        DemResampler.resample(full, w, h));
            }
            case "jacksboro":
                return new StudyDem(name, "Jacksboro SRTM 3″ (lat/lon)",
                        DemReader.read(dir.resolve("jacksboro_srtm3s_wgs84.flt")));
            case "luxembourg":
                return new StudyDem(name, "Luxembourg 30″ (lat/lon; no-data outside the border)",
                        DemReader.read(dir.resolve("luxembourg_srtm30s_wgs84.flt")));
            case "vancouver":
                return new StudyDem(name, "Vancouver Island topo-bathy 2′ (Mercator)",
                        DemReader.read(dir.resolve("vancouver-island_topobathy_2min_mercator.flt")));
            case "maungawhau":
                return new StudyDem(name, "Maungawhau volcano 10 m",
                        DemReader.read(dir.resolve("maungawhau-volcano_10m_nztm-approx.flt")));
            case "fractal4000":
                return new StudyDem(name, "fractal 4000×4000 at 30 m (FractalDem seed 846)",
                        FractalDem.dem(4000, 846L));
            default:
                throw new IllegalArgumentException("unknown DEM '" + name + "'; expected one of " + NAMES);
        }
    }
}
