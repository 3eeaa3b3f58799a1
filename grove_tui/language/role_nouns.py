"""People named by their part in a place's life that the general list lacks: the roles of courts,
ports and ferries, schools, shops, factories, theatres, churches and stadiums, people named by
what they did or what was done to them, workmates ("his mate") and the jury (a collective of
twelve). The lexicon adds them to its person nouns."""

from __future__ import annotations

ROLE_NOUNS = frozenset("""
juror witness defendant accused prosecutor magistrate bailiff advocate claimant plaintiff appellant
litigant stenographer solicitor paralegal suspect prisoner inmate detainee convict offender
harbourmaster deckhand stevedore docker boatman mariner seafarer skipper bosun helmsman coastguard
classmate schoolmate prefect headboy headgirl invigilator examiner examinee fresher postgrad undergrad
shelfstacker packer machinist welder fitter operative millworker
stagehand theatregoer playgoer cinemagoer moviegoer concertgoer usherette projectionist prompter
verger churchwarden sexton deacon curate bishop congregant parishioner bridesmaid groomsman pallbearer
linesman tout mourner groundstaff
owner shoplifter thief burglar intruder trespasser protester demonstrator vandal pickpocket
mate jury
girlfriend boyfriend fiance fiancee spouse missus
""".split())
