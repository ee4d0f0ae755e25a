package io.github.jdem846.shadow;

/**
 * The terrain walked so far on each line of a block ({@link HorizonSweep}), as points (P, z) with the distance P
 * growing in the walk's direction, and the horizon it makes for a point farther on: every sample ({@link
 * HorizonHulls}) or those within a search radius ({@link WindowedHulls}).
 */
interface LineHorizons {

    /** Adds the sample (px, pz) to line q; px must exceed every distance added to that line before. */
    void push(int q, double px, double pz);

    /**
     * The steepest slope (z − pz)/(px − x) from (px, pz) to line q's samples that count, at least 0 (terrain beyond
     * the grid, or none, is a horizon at 0°). The distances px of successive queries on a line do not decrease.
     *
     * @param px a distance beyond every sample of the line
     */
    double slope(int q, double px, double pz);
}
