package io.github.jdem846.bench;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.raster.Dem;
import io.github.jdem846.raster.DemResampler;
import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The DEMs of the accuracy study: the real DEMs of testdata/dem, a coarse (≈ 210 m) area average of Big Tujunga
 * standing in for a coarse mountain DEM, and the 4000² fractal.
 *
 * @param name        short name used on the command line and in file names
 * @param description one line for the tables
 * @param dem         the elevations
 */
record StudyDem(String name, String description, Dem dem) {

    /** Big Tujunga is area-averaged by this factor per axis for the coarse DEM (30 m → ≈ 210 m). */
    static final int COARSE_FACTOR = 7;

    private static final Map<String, String> DESCRIPTIONS = new LinkedHashMap<>();

    static {
        DESCRIPTIONS.put("bigtujunga", "Big Tujunga SRTM 30 m (UTM 11N), 1197×643");
        DESCRIPTIONS.put("bigtujunga-210m", "Big Tujunga area-averaged 7×7 (DemResampler) to 171×92, ≈ 210 m cells");
        DESCRIPTIONS.put("jacksboro", "Jacksboro SRTM 3″ (lat/lon, ≈ 74 × 92 m), 403×344");
        DESCRIPTIONS.put("luxembourg", "Luxembourg 30″ (lat/lon), 95×90, no-data outside the border");
        DESCRIPTIONS.put("vancouver", "Vancouver Island topo-bathy 2′ (Mercator), 120×91");
        DESCRIPTIONS.put("maungawhau", "Maungawhau volcano 10 m, 61×87");
        DESCRIPTIONS.put("fractal4000", "fractal 4000×4000 at 30 m (FractalDem seed 846)");
    }

    /** Every name {@link #load} knows, in report order. */
    static final List<String> NAMES = List.copyOf(DESCRIPTIONS.keySet());

    /** The description of DEM {@code name} (the name itself when unknown). */
    static String describe(String name) {
        return DESCRIPTIONS.getOrDefault(name, name);
    }

    /** Loads DEM {@code name}; real DEMs are read from {@code testdata}/dem. */
    static StudyDem load(String name, Path testdata) throws IOException {
        Path dir = testdata.resolve("dem");
        Dem dem = switch (name) {
            case "bigtujunga" -> DemReader.read(dir.resolve("bigtujunga_srtm30m_utm11n.flt"));
            case "bigtujunga-210m" -> {
                Dem full = DemReader.read(dir.resolve("bigtujunga_srtm30m_utm11n.flt"));
                yield DemResampler.resample(full, (int) Math.round((double) full.width() / COARSE_FACTOR),
                        (int) Math.round((double) full.height() / COARSE_FACTOR));
            }
            case "jacksboro" -> DemReader.read(dir.resolve("jacksboro_srtm3s_wgs84.flt"));
            case "luxembourg" -> DemReader.read(dir.resolve("luxembourg_srtm30s_wgs84.flt"));
            case "vancouver" -> DemReader.read(dir.resolve("vancouver-island_topobathy_2min_mercator.flt"));
            case "maungawhau" -> DemReader.read(dir.resolve("maungawhau-volcano_10m_nztm-approx.flt"));
            case "fractal4000" -> FractalDem.dem(4000, 846L);
            default -> throw new IllegalArgumentException("unknown DEM '" + name + "'; expected one of " + NAMES);
        };
        return new StudyDem(name, describe(name), dem);
    }
}
