package io.github.jdem846.spark;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.Window;
import io.github.jdem846.raster.ElevationStatistics;
import java.io.PrintWriter;
import java.io.StringWriter;
import org.apache.spark.api.java.function.Function;

/**
 * One Spark task of the range stage: the elevation range of a band of rows of the DEM (or mosaic), read at full
 * resolution on the executor; the bands' ranges merged are the whole DEM's, as {@link DemReader#statistics} gives it
 * on one machine.
 */
final class RangeTask implements Function<int[], ElevationStatistics> {

    private static final long serialVersionUID = 1L;

    private final TileArguments arguments;
    private final InputRefs inputs;

    RangeTask(TileArguments arguments, InputRefs inputs) {
        this.arguments = arguments;
        this.inputs = inputs;
    }

    /** @param band first row, row count and the grid's width */
    @Override
    public ElevationStatistics call(int[] band) throws Exception {
        var input = arguments.job(inputs.executorFiles(), new PrintWriter(new StringWriter())).input();
        return DemReader.statistics(input, new Window.Cells(0, band[0], band[2], band[1]));
    }
}
