/* report.c — the design dossier's driver: it sizes the mass unit, opens
 * the document and writes the template's sections in its order, each from
 * the file that holds it (report_cover.c, report_tables.c, report_figs.c,
 * report_prop.c); the sections share the helpers of report_util.c.
 *
 * Every number printed comes from the const solve_result; nothing is
 * recomputed beyond ratios, unit conversions and sums, so the dossier says
 * exactly what result.json says.
 */
#include "pdf/report.h"

#include <stdio.h>

#include "pdf/doc.h"
#include "pdf/report_cover.h"
#include "pdf/report_figs.h"
#include "pdf/report_prop.h"
#include "pdf/report_tables.h"
#include "pdf/report_util.h"

/* Aircraft lighter than this get their masses in grams. */
#define REP_GRAM_BELOW_KG 2.0

/* ---- sensitivity (optional, template switch) ----------------------------- */

static void
sec_sensitivity(struct rep *rp, const char *title)
{
	if (rp->in->sensitivity != NULL) {
		rp->in->sensitivity(rp->d, rp->tpl, rp->in->sensitivity_arg);
		return;
	}
	report_heading(rp, title);
	doc_paragraph(rp->d, "The trade study was not run for this dossier; "
	    "`aeroeval sensitivity` produces it.");
}

/* ---- the document -------------------------------------------------------- */

int
report_render(const struct report_input *in, unsigned char **pdf, size_t *n,
              char *err, size_t errlen)
{
	*pdf = NULL;
	*n = 0;
	if (in == NULL || in->r == NULL || in->tpl == NULL) {
		snprintf(err, errlen, "report: no result or no template");
		return -1;
	}
	const struct solve_result *r = in->r;
	const struct mission_spec *m = &r->mission;
	struct rep rp = { .in = in, .r = r, .tpl = in->tpl };
	rp.rec = res_record(r, &rp.buildable);
	rp.rec_ok = rp.buildable && rp.rec->feasible;
	res_figures(r, &rp.fig);
	int small = rp.rec->mass.total_kg < REP_GRAM_BELOW_KG &&
	            r->custom.mass.total_kg < REP_GRAM_BELOW_KG &&
	            r->baseline.mass.total_kg < REP_GRAM_BELOW_KG;
	rp.mass_scale = small ? 1000.0 : 1.0;
	rp.mass_unit = small ? "g" : "kg";
	rp.mass_dec = small ? 1 : 3;

	char title[SPEC_STR_MAX + 32], number[32];
	snprintf(title, sizeof title, "%s", m->report.title[0] != '\0' ? m->report.title : "Design dossier");
	struct doc_info info = {
		.title = title,
		.mission = in->mission_name != NULL ? in->mission_name : m->name,
		.author = m->report.author[0] != '\0' ? m->report.author : NULL,
		.subject = m->report.client[0] != '\0' ? m->report.client : "Multirotor UAV sizing",
		.date = in->date != NULL && in->date[0] != '\0' ? in->date : NULL,
		.doc_number = report_doc_number(r, number, sizeof number),
		.revision = m->report.revision,
		.input_sha256 = r->input_sha256,
		.catalogue_sha256 = r->catalogue_sha256,
	};
	rp.d = doc_alloc(in->tpl, &info);
	doc_set_transcript(rp.d, in->transcript);

	/* A mission beyond reach with no shorter flight that sizes has no
	 * aircraft to describe: the pages of a design are left out rather
	 * than filled with a diverged iterate's figures. */
	bool no_design = r->ceiling.valid && !r->ceiling.shown;
	int first = 1;
	for (int i = 0; i < in->tpl->n_sections; i++) {
		const struct template_section *s = &in->tpl->sections[i];
		if (!s->enabled)
			continue;
		if (no_design && s->id != TEMPLATE_SEC_COVER && s->id != TEMPLATE_SEC_RATIONALE
		    && s->id != TEMPLATE_SEC_CONVERGENCE && s->id != TEMPLATE_SEC_CHECKS
		    && s->id != TEMPLATE_SEC_APPENDIX)
			continue;
		switch (s->id) {
		case TEMPLATE_SEC_COVER:
			report_sec_cover(&rp, first);
			report_sec_control(&rp);
			break;
		case TEMPLATE_SEC_SUMMARY: report_sec_summary(&rp, s->title); break;
		case TEMPLATE_SEC_RATIONALE: report_sec_rationale(&rp, s->title); break;
		case TEMPLATE_SEC_MASS: report_sec_mass(&rp, s->title); break;
		case TEMPLATE_SEC_MISSION: report_sec_mission(&rp, s->title); break;
		case TEMPLATE_SEC_THERMAL: report_sec_thermal(&rp, s->title); break;
		case TEMPLATE_SEC_STRUCTURE: report_sec_structure(&rp, s->title); break;
		case TEMPLATE_SEC_PROPULSION: report_sec_propulsion(&rp, s->title); break;
		case TEMPLATE_SEC_CONVERGENCE: report_sec_convergence(&rp, s->title); break;
		case TEMPLATE_SEC_ENDURANCE: report_sec_endurance(&rp, s->title); break;
		case TEMPLATE_SEC_BOM: report_sec_bom(&rp, s->title); break;
		case TEMPLATE_SEC_CHECKS: report_sec_checks(&rp, s->title); break;
		case TEMPLATE_SEC_APPENDIX: report_sec_appendix(&rp, s->title); break;
		case TEMPLATE_SEC_SENSITIVITY: sec_sensitivity(&rp, s->title); break;
		case TEMPLATE_SEC_MAX: break;
		}
		first = 0;
	}
	if (in->mission_bytes != NULL && in->mission_file_name != NULL)
		doc_attach(rp.d, in->mission_file_name, in->mission_bytes, in->mission_len);
	int rc = doc_save_mem(rp.d, pdf, n);
	if (rc != 0)
		snprintf(err, errlen, "dossier: %s", doc_error(rp.d) != NULL ? doc_error(rp.d) : "cannot render");
	doc_free(rp.d);
	return rc == 0 ? 0 : -1;
}
